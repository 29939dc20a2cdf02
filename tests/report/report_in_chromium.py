"""`clinch report` on a deck, loaded in headless Chromium with the network off.

Runs the deck, a three-setting study of it, and `clinch report RUN --study` (with --golden and
the case's compare.args when a verification case directory is given), then:
- the page is self-contained: no script, stylesheet, image or frame to fetch, and Chromium
  (every request sent to a dead proxy) renders it whole;
- every plot rendered: a probe added to a copy of the page reports each figure's box and its
  SVG text; in a screenshot of the whole page each box is non-blank (enough non-white pixels and
  colours);
- the expected plots are there, counted from the history table independently of the page: one
  force-motion plot per connector and component that moves and carries force (its CU column and
  one of CEF, CVF, CSF, CRF, CTF above 1e-6 of the largest column of the same quantity: force,
  moment, displacement or rotation), one time-history plot per connector and per node, one
  convergence plot, one golden plot per golden column, one work-precision plot;
- each force-motion plot's motion axis names the motion with its Abaqus name (CU1..3, CUR1..3
  for rotations, in [rad]) and it has one curve per part above round-off (CEF, CVF, CSF, CRF,
  CTF); the components left out are listed in a table below the connector's plots;
- the time-history plots name the steps of the .sta (`STEP n: name` lines) at their starts;
- each golden plot marks the worst deviation at the time this script finds on its own
  (largest |r - g| / (atol + rtol max(|g|, largest |g|)) over the golden rows, the result
  interpolated linearly at golden times);
- the convergence plot marks as many cutbacks as the .sta has cut-back attempts.

Skipped (exit 77) only when no Chromium is installed.
With --friction-loop (the driven hinge of decks/verification/driven_hinge_friction): exactly one
force-motion plot, component 4, with the friction moment and the actuator moment (-CRM1) against
CUR1 and no total moment (CTM1 is round-off), and components 1, 2, 3, 5, 6 listed as carrying
nothing.

Usage: report_in_chromium.py CLINCH DECK WORK [--golden-dir CASE_DIR] [--friction-loop]
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
    # Times within 1e-12 of the largest time are the same time, as `clinch compare` matches them
    # (0.1 + 0.2 against 0.3); the last row at that time counts.
    same = 1e-12 * max(abs(ts[-1]), abs(t))
    at = [i for i in range(len(ts)) if abs(ts[i] - t) <= same]
    if at:
        return vs[at[-1]]
    for i in range(1, len(ts)):
        if ts[i] >= t:
            return vs[i - 1] + (t - ts[i - 1]) / (ts[i] - ts[i - 1]) * (vs[i] - vs[i - 1])
    return vs[-1] if t >= ts[-1] else vs[0]


# Abaqus's letters for rotational components (output-variables.md §1.1), for a golden table in
# Abaqus's names: CTM1@e is the run's CTF4@e.
ABAQUS_ROTATIONS = {"CTM": "CTF", "CEM": "CEF", "CVM": "CVF", "CSM": "CSF", "CRM": "CRF",
                    "CNM": "CNF", "CUR": "CU", "CURE": "CUE", "CURP": "CUP", "CCUR": "CCU"}


def run_name(name):
    m = re.match(r"^([A-Z]+)([1-3])@(.+)$", name)
    if m and m.group(1) in ABAQUS_ROTATIONS:
        return f"{ABAQUS_ROTATIONS[m.group(1)]}{int(m.group(2)) + 3}@{m.group(3)}"
    return name


def worst_times(history, golden, rtol, atol):
    """Per golden column, the total time of its worst row and the deviation over the allowance
    at each golden time."""
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
        hv = [r[h_names.index(run_name(name))] for r in h_rows]
        ratios = [abs(interpolate(ht, hv, t) - x) / (atol + rtol * max(abs(x), scale))
                  for t, x in zip(gt, g)]
        worst[name] = (gt[max(range(len(ratios)), key=lambda i: ratios[i])],
                       dict(zip(gt, ratios)))
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
    case_dir = sys.argv[sys.argv.index("--golden-dir") + 1] if "--golden-dir" in sys.argv else None
    friction_loop = "--friction-loop" in sys.argv
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
    keys = ("step", "increment", "step_time", "total_time")
    names = history[0]
    columns = [c for c in names if c not in keys]
    parsed = {c: re.match(r"^([A-Z]+?)([1-6]?)(-[^@]*)?@(.+)$", c).groups() for c in columns}
    nodal = {"U", "UR", "RF", "RM"}
    forces = {"CTF", "CEF", "CVF", "CSF", "CRF", "CCF", "CNF", "CALPHAF", "RF", "RM"}
    motions = {"CU", "CUE", "CUP", "CCU", "CP", "CASU", "U", "UR"}

    def quantity(c):
        v, k, _, _ = parsed[c]
        rotational = (k and int(k) >= 4) or v in ("UR", "RM")
        if v in forces:
            return "moment" if rotational else "force"
        if v in motions:
            return "rotation" if rotational else "displacement"
        return "other"

    peak = {c: max(abs(r[names.index(c)]) for r in history[1]) for c in columns}
    scale = {}
    for c in columns:
        scale[quantity(c)] = max(scale.get(quantity(c), 0.0), peak[c])

    def live(c):
        return c in peak and peak[c] > 1e-6 * scale[quantity(c)]

    connectors = {w for v, _, _, w in parsed.values() if v not in nodal}
    nodes = {w for v, _, _, w in parsed.values() if v in nodal}
    plotted = {}  # (connector, component) -> the parts drawn
    for w in connectors:
        for k in range(1, 7):
            parts = [v for v in ("CEF", "CVF", "CSF", "CRF", "CTF") if live(f"{v}{k}@{w}")]
            if live(f"CU{k}@{w}") and parts:
                plotted[(w, k)] = parts
    expected = {"force-motion": len(plotted), "history-connector": len(connectors),
                "history-node": len(nodes), "convergence": 1,
                "golden": max(len(golden[0]) - 4, 0), "work-precision": 1}
    expected = {k: v for k, v in expected.items() if v}
    counts = {}
    for fig in figures:
        counts[fig["kind"]] = counts.get(fig["kind"], 0) + 1
    assert counts == expected, (counts, expected)

    # Axis labels, curves, step names.
    with open(os.path.join(run_dir, case + ".sta")) as f:
        step_names = [line.split(": ", 1)[1].strip() for line in f if line.startswith("STEP ")]
    assert step_names, "the .sta names no step"
    for fig in figures:
        if fig["kind"] == "force-motion":
            w, k = fig["data"]["connector"], int(fig["data"]["component"])
            labels = " ".join(fig["text"])
            motion = f"CU{k}@{w}" if k <= 3 else f"CUR{k - 3}@{w}"
            assert motion in labels, (motion, fig["text"])
            if k >= 4:
                assert "[rad]" in labels, fig["text"]
            drawn = sorted(i[len("curve-"):] for i in fig["ids"] if i.startswith("curve-"))
            assert drawn == sorted(plotted[(w, k)]), (w, k, drawn, plotted[(w, k)])
        if fig["kind"].startswith("history-"):
            labels = " ".join(fig["text"])
            for name in step_names:
                assert name in labels, (name, fig["text"])
        if fig["kind"] == "golden":
            assert any(fig["data"]["column"] in t for t in fig["text"]), fig["text"]
        if fig["kind"] in ("convergence", "work-precision"):
            assert any("norm" in t or "error" in t for t in fig["text"]), fig["text"]
    # Every component of a connector is plotted or listed as left out.
    for w in connectors:
        for k in range(1, 7):
            if (w, k) in plotted or f"CU{k}@{w}" not in names:
                continue
            assert re.search(rf'<table class="left-out" data-connector="{re.escape(w)}">.*?'
                             rf"<tr><td>{k}</td>", text, re.S), (w, k)
    if friction_loop:
        (loop,) = [fig for fig in figures if fig["kind"] == "force-motion"]
        assert loop["data"]["component"] == "4", loop["data"]
        curves = {i for i in loop["ids"] if i.startswith("curve-")}
        assert curves == {"curve-CEF", "curve-CSF", "curve-CRF"}, curves
        labels = " ".join(loop["text"])
        assert "CSM1 (friction)" in labels and "-CRM1 (actuator" in labels, loop["text"]
        assert "CUR1@1: relative rotation about axis 1 [rad]" in labels, loop["text"]
        assert "connector 1: moments against CUR1" in loop["text"], loop["text"]
        for k in (1, 2, 3, 5, 6):
            assert f"<tr><td>{k}</td><td>carries nothing" in text, k

    # Cutbacks: one band per cut-back attempt of the .sta.
    with open(os.path.join(run_dir, case + ".sta")) as f:
        cut = sum(1 for line in f if len(line.split()) == 9 and line.split()[3] == "U"
                  and line.split()[0].isdigit())
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
        # The mark is at the worst row, or at a row as bad up to 1e-6 of the allowance: where
        # every deviation is round-off (1e-16 against an allowance of 1e-9), rows tie.
        at, ratios = worst[name]
        tied = max(ratios.values()) - ratios.get(marked, -1.0) <= 1e-6
        assert abs(marked - at) <= 1e-12 * max(1.0, abs(marked)) or tied, (name, marked, at)
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
