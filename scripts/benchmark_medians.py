"""Google Benchmark JSON (aggregates) on stdin -> one line per case: the median time per item,
items per second, and the time per item over that of a reference case (default
SpotWeldPlasticUpdate, the plastic spot-weld update at 2-20 x first yield).
Usage: benchmark_medians.py [REFERENCE_CASE] < results.json"""
import json
import sys

reference = sys.argv[1] if len(sys.argv) > 1 else "SpotWeldPlasticUpdate"
rows = {}
for b in json.load(sys.stdin)["benchmarks"]:
    if b.get("aggregate_name") == "median":
        rows[b["run_name"].removeprefix("BM_")] = b
base = rows.get(reference)
print(f"{'case (medians)':40} {'ns/item':>9} {'items/s':>10} {'time / ' + reference:>30}")
for name, b in rows.items():
    rate = b["items_per_second"]
    ratio = f"{base['items_per_second'] / rate:.2f}" if base else "-"
    print(f"{name:40} {1e9 / rate:9.1f} {rate:10.3g} {ratio:>30}")
