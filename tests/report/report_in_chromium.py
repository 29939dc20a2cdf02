"""`clinch report` on a deck, loaded in headless Chromium with the network off.

Runs the deck, a three-setting study of it, and `clinch report RUN --study` (with --golden and
the case's compare.args when a verification case directory is given), then:
- the page is self-contained: no script, stylesheet, image or frame to fetch, and Chromium
  (every request sent to a dead proxy) renders it whole;
- every plot rendered: a probe added to a copy of the page reports each figure's box and its
  SVG text; in a screenshot of the whole page each box is non-blank (enough non-white pixels and
  colours);
- the expected plots are there, counted from the history header independently of the page:
  one force-motion plot per connector and component that has CTF and CU, one time-history plot
  per connector and per node, one convergence plot, one golden plot per golden column, one
  work-precision plot;
- axes are labelled with the variables (CTFi@e and CUi@e on force-motion plots, rotational
  motions in [rad]), and each force-motion plot has one curve per motion the history holds
  (CU, and the elastic and plastic parts CUE and CUP);
- each golden plot marks the worst deviation at the time this script finds on its own
  (largest |r - g| / (atol + rtol max(|g|, largest |g|)) over the golden rows, the result
  interpolated linearly at golden times);
- the convergence plot marks as many cutbacks as the .sta has cut-back attempts.

Skipped (exit 77) only when no Chromium is installed.
Usage: report_in_chromium.py CLINCH DECK WORK [--golden-dir CASE_DIR]
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys

from PIL import Image

CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
OFFLINE = ["--headless", "--disable-gpu", "--no-sandbox", "--no-first-run",
           "--proxy-server=127.0.0.1:9", "--host-resolver-rules=MAP * ~NOTFOUND",
           "--disable-background-networking", "--hide-scrollbars"]
PROBE = """<script>
window.addEventListener('load', () => {
  const figures = [...document.querySelectorAll('figure.plot')].map(f => {
    const r = f.querySelector('svg').getBoundingClientRect();
    return {kind: f.dataset.kind, data: {...f.dataset},
            box: [r.left + scrollX, r.top + scrollY, r.width, r.height],
            text: [...f.querySelectorAll('svg text')].map(t => t.textContent),
            ids: [...f.querySelectorAll('svg [id]')].map(e => e.id)};
  });
  const out = document.createElement('pre');
  out.id = 'probe';
  out.textContent = JSON.stringify({height: document.documentElement.scrollHeight,
                                    figures: figures});
  document.body.appendChild(out);
});
</script>"""


def read_table(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def interpolate(ts, vs, t):
    for i in range(1, len(ts)):
        if ts[i] >= t:
            if ts[i] == t:
                return vs[i]
            return vs[i - 1] + (t - ts[i - 1]) / (ts[i] - ts[i - 1]) * (vs[i] - vs[i - 1])
    return vs[-1] if t >= ts[-1] else vs[0]


def worst_times(history, golden, rtol, atol):
    """Per golden column, the total time of its worst row."""
    h_names, h_rows = history
    g_names, g_rows = golden
    ht = [r[h_names.index("total_time")] for r in h_rows]
    gt = [r[g_names.index("total_time")] for r in g_rows]
    worst = {}
    for j, name in enumerate(g_names):
        if name in ("step", "increment", "step_time", "total_time"):
            continue
        g = [r[j] for r in g_rows]
        scale = max(abs(x) for x in g)
        hv = [r[h_names.index(name)] for r in h_rows]
        ratios = [abs(interpolate(ht, hv, t) - x) / (atol + rtol * max(abs(x), scale))
                  for t, x in zip(gt, g)]
        worst[name] = gt[max(range(len(ratios)), key=lambda i: ratios[i])]
    return worst


def chromium(args):
    for name in CHROMIUM_NAMES:
        path = shutil.which(name)
        if path:
            return subprocess.run([path] + OFFLINE + args, capture_output=True, text=True,
                                  timeout=300)
    return None


def main():
    clinch, deck, work = sys.argv[1:4]
    case_dir = sys.argv[5] if len(sys.argv) > 5 and sys.argv[4] == "--golden-dir" else None
    if not any(shutil.which(n) for n in CHROMIUM_NAMES):
        print("skipped: no Chromium found (" + ", ".join(CHROMIUM_NAMES) + ")")
        return 77
    case = os.path.splitext(os.path.basename(deck))[0]
    golden_args, rtol, atol = [], 1e-6, 1e-12
    if case_dir:
        golden_path = os.path.join(case_dir, "golden.csv")
        with open(os.path.join(case_dir, "compare.args")) as f:
            args = f.read().split()
        rtol = float(args[args.index("--rtol") + 1]) if "--rtol" in args else rtol
        atol = float(args[args.index("--atol") + 1]) if "--atol" in args else atol
        golden_args = ["--golden", golden_path, "--rtol", str(rtol), "--atol", str(atol)]
    shutil.rmtree(work, ignore_errors=True)
    run_dir = os.path.join(work, "run")
    subprocess.run([clinch, "run", "--quiet", "--out", run_dir, deck], check=True)
    subprocess.run([clinch, "study", "--quiet", "--levels", "3", "--work",
                    os.path.join(work, "study"), deck], check=True)
    page = os.path.join(work, "report.html")
    subprocess.run([clinch, "report", run_dir] + golden_args + [
                    "--study", os.path.join(work, "study", case + ".study.csv"), "-o", page],
                   check=True)
    with open(page) as f:
        text = f.read()
    # Self-contained: nothing that a browser would fetch.
    for pattern in (r"<script", r"<link", r"<img", r"<iframe", r"@import", r"url\(\s*['\"]?http",
                    r"(src|href)\s*=\s*['\"]?(https?:|//)"):
        assert not re.search(pattern, text, re.I), f"the page refers to something: {pattern}"

    dom = chromium(["--dump-dom", "file://" + os.path.abspath(page)])
    assert dom.returncode == 0, dom.stderr[-2000:]
    assert dom.stdout.count('<figure class="plot"') == text.count('<figure class="plot"')

    probe_page = os.path.join(work, "report-probe.html")
    with open(probe_page, "w") as f:
        f.write(text.replace("</body>", PROBE + "</body>"))
    dumped = chromium(["--dump-dom", "--window-size=1400,900", "--virtual-time-budget=5000",
                       "file://" + os.path.abspath(probe_page)])
    probe = re.search(r'<pre id="probe">(.*?)</pre>', dumped.stdout, re.S)
    assert probe, "the probe did not run: " + dumped.stderr[-2000:]
    probe = json.loads(probe.group(1).replace("&quot;", '"').replace("&lt;", "<")
                       .replace("&gt;", ">").replace("&amp;", "&"))
    figures = probe["figures"]

    # Expected plots, from the history header.
    history = read_table(os.path.join(run_dir, case + ".history.csv"))
    golden = read_table(golden_path) if case_dir else ([], [])
    columns = [c for c in history[0] if c not in ("step", "increment", "step_time", "total_time")]
    parsed = [re.match(r"^([A-Z]+?)([1-6]?)(-[^@]*)?@(.+)$", c).groups() for c in columns]
    nodal = {"U", "UR", "RF", "RM"}
    connectors = {w for v, _, _, w in parsed if v not in nodal}
    nodes = {w for v, _, _, w in parsed if v in nodal}
    pairs = {(w, int(k)) for v, k, _, w in parsed if v == "CTF" and k
             and ("CU", k, None, w) in parsed}
    expected = {"force-motion": len(pairs), "history-connector": len(connectors),
                "history-node": len(nodes), "convergence": 1,
                "golden": max(len(golden[0]) - 4, 0), "work-precision": 1}
    expected = {k: v for k, v in expected.items() if v}
    counts = {}
    for fig in figures:
        counts[fig["kind"]] = counts.get(fig["kind"], 0) + 1
    assert counts == expected, (counts, expected)

    # Axis labels.
    for fig in figures:
        if fig["kind"] == "force-motion":
            w, k = fig["data"]["connector"], int(fig["data"]["component"])
            labels = " ".join(fig["text"])
            assert f"CTF{k}@{w}" in labels and f"CU{k}@{w}" in labels, fig["text"]
            if k >= 4:
                assert "[rad]" in labels, fig["text"]
            # One curve per motion the history has: total, elastic and plastic parts.
            for part in ("CU", "CUE", "CUP"):
                present = f"{part}{k}@{w}" in history[0]
                assert (f"curve-{part}" in fig["ids"]) == present, (part, k, w, fig["ids"])
        if fig["kind"] == "golden":
            assert any(fig["data"]["column"] in t for t in fig["text"]), fig["text"]
        if fig["kind"] in ("convergence", "work-precision"):
            assert any("norm" in t or "error" in t for t in fig["text"]), fig["text"]

    # Cutbacks: one band per cut-back attempt of the .sta.
    with open(os.path.join(run_dir, case + ".sta")) as f:
        cut = sum(1 for line in f if len(line.split()) == 9 and line.split()[3] == "U")
    (conv,) = [fig for fig in figures if fig["kind"] == "convergence"]
    assert int(conv["data"]["cutbacks"]) == cut, (conv["data"], cut)
    assert sum(1 for i in conv["ids"] if i.startswith("cutback")) == cut, conv["ids"]

    # The golden overlays mark the worst deviation where it is.
    worst = worst_times(history, golden, rtol, atol) if case_dir else {}
    for fig in figures:
        if fig["kind"] != "golden":
            continue
        name = fig["data"]["column"]
        assert "worst-deviation" in fig["ids"], (name, fig["ids"])
        marked = float(fig["data"]["worstTime"])
        assert abs(marked - worst[name]) <= 1e-12 * max(1.0, abs(marked)), (name, marked,
                                                                            worst[name])
        assert any(t.startswith("worst |r - g| =") and f"t = {marked:g}" in t
                   for t in fig["text"]), (name, fig["text"])

    # Every plot is non-blank in a screenshot of the whole page.
    shot = os.path.join(work, "report.png")
    height = min(int(probe["height"]) + 20, 32000)
    taken = chromium([f"--screenshot={shot}", f"--window-size=1400,{height}",
                      "file://" + os.path.abspath(page)])
    assert taken.returncode == 0 and os.path.exists(shot), taken.stderr[-2000:]
    image = Image.open(shot).convert("RGB")
    for fig in figures:
        x, y, w, h = fig["box"]
        assert w > 100 and h > 100, (fig["kind"], fig["box"])
        crop = image.crop((int(x), int(y), int(x + w), int(min(y + h, image.height))))
        pixels = list(crop.getdata())
        inked = sum(1 for p in pixels if sum(p) < 720) / len(pixels)
        colours = len(set(pixels))
        assert inked > 0.02 and colours > 8, (fig["kind"], fig["data"], inked, colours)
    print(f"{case}: {len(figures)} plots rendered in Chromium offline: {counts}; "
          f"{cut} cutbacks marked; screenshot {shot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
