"""Google Benchmark JSON (aggregates) on stdin -> one line per case: the median time per item,
items per second and, for a case named <single>Batched/<n>, its ratio to <single>."""
import json
import sys

rows = {}
for b in json.load(sys.stdin)["benchmarks"]:
    if b.get("aggregate_name") == "median":
        rows[b["run_name"].removeprefix("BM_")] = b
print(f"{'case (medians)':40} {'ns/item':>9} {'items/s':>10} {'vs one at a time':>17}")
for name, b in rows.items():
    rate = b["items_per_second"]
    single = rows.get(name.split("Batched")[0]) if "Batched" in name else None
    ratio = f"{rate / single['items_per_second']:.2f}x" if single else ""
    print(f"{name:40} {1e9 / rate:9.1f} {rate:10.3g} {ratio:>17}")
