"""What the run-output tests share: a deck of many small increments, and the check that a history
table left by a run that stopped early (full disk, signal, SIGKILL) holds only converged
increments: every complete row equals the row of an uninterrupted run, and only the last line may
be cut short."""

import os


def write_chain_deck(path, connectors, increment, period=1.0, first_only=False, frequency=1):
    """CARTESIAN connectors from a held node to `connectors` nodes that are pulled along 1 and
    loaded along 2, with DIRECT increments of `increment`: a history of 6 columns per connector
    (or, `first_only`, of the first connector alone) and one row every `frequency` increments, as
    many increments as wanted."""
    lines = ["*NODE", "1, 0., 0., 0."]
    lines += [f"{i + 1}, {1 + 0.1 * i}, 1., 0." for i in range(1, connectors + 1)]
    lines += ["*ELEMENT, TYPE=CONN3D2, ELSET=C"]
    lines += [f"{i}, 1, {i + 1}" for i in range(1, connectors + 1)]
    lines += ["*ELSET, ELSET=FIRST", "1", "*NSET, NSET=MOVED"]
    lines += [str(i + 1) for i in range(1, connectors + 1)]
    lines += ["*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B", "CARTESIAN,",
              "*CONNECTOR BEHAVIOR, NAME=B"]
    for component in (1, 2, 3):
        lines += [f"*CONNECTOR ELASTICITY, COMPONENT={component}", "100."]
    increments = round(period / increment)
    lines += ["*BOUNDARY", "1, ENCASTRE", f"*STEP, INC={2 * increments}", "*STATIC, DIRECT",
              f"{increment}, {period}", "*BOUNDARY", "MOVED, 1, 1, 0.5", "*CLOAD",
              "MOVED, 2, 10."]
    if first_only:
        lines += [f"*OUTPUT, HISTORY, FREQUENCY={frequency}", "*ELEMENT OUTPUT, ELSET=FIRST",
                  "CTF, CU"]
    lines += ["*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def read_lines(path):
    """The complete lines of a file (without their newline) and the partial last line ('' when
    the file ends with a newline)."""
    with open(path, "rb") as f:
        text = f.read().decode()
    *complete, partial = text.split("\n")
    return complete, partial


def check_history(path, reference_lines):
    """Problems (a list of strings; empty when none) with the history at `path` against the
    complete history `reference_lines` of the same deck: the header and every complete row equal
    the reference's, rows in order of increasing total_time, each a number in every column; a
    partial last line is the start of the next reference row. Returns (problems, rows)."""
    problems = []
    complete, partial = read_lines(path)
    if not complete:
        return [f"{path}: no complete header line"], 0
    if complete[0] != reference_lines[0]:
        problems.append(f"{path}: header differs from the uninterrupted run's")
    times = []
    for number, line in enumerate(complete[1:], start=1):
        fields = line.split(",")
        try:
            values = [float(v) for v in fields]
        except ValueError:
            problems.append(f"{path}:{number + 1}: not a row of numbers: {line[:80]!r}")
            continue
        if len(fields) != len(complete[0].split(",")):
            problems.append(f"{path}:{number + 1}: {len(fields)} fields")
        times.append(values[3])
        if number >= len(reference_lines) or line != reference_lines[number]:
            problems.append(f"{path}:{number + 1}: not the converged increment of the "
                            f"uninterrupted run: {line[:80]!r}")
    if any(b <= a for a, b in zip(times, times[1:])):
        problems.append(f"{path}: total_time does not increase")
    rows = len(complete) - 1
    if partial:
        nxt = rows + 1
        if nxt >= len(reference_lines) or not reference_lines[nxt].startswith(partial):
            problems.append(f"{path}: the partial last line is not the start of the next row")
    return problems, rows


def history_keys(path):
    """(step, increment) of each complete row; check_history reports the rows that do not parse."""
    complete, _ = read_lines(path)
    keys = set()
    for line in complete[1:]:
        try:
            keys.add(tuple(int(float(v)) for v in line.split(",")[:2]))
        except ValueError:
            pass
    return keys


def status_problems(files, frequency=1):
    """Problems: each converged attempt in the status file whose row is not in the history (the
    row is written before the status line, so the status file is never ahead); with a FREQUENCY,
    only the increments it writes have rows."""
    keys = history_keys(files["history.csv"])
    complete, _ = read_lines(files["sta"])
    problems = []
    for line in complete[1:]:
        fields = line.split()
        # step inc att equil total times...: 8 fields; a cut-back attempt has a 9th, `U`.
        converged = len(fields) == 8 and fields[0].isdigit()
        due = converged and int(fields[1]) % frequency == 0
        if due and (int(fields[0]), int(fields[1])) not in keys:
            problems.append(f"{files['sta']}: increment {fields[1]} is in the status file but "
                            f"not in the history")
    return problems


def last_line(path):
    complete, partial = read_lines(path)
    return partial or (complete[-1] if complete else "")


def job_files(directory, job):
    return {ext: os.path.join(directory, f"{job}.{ext}") for ext in ("history.csv", "sta", "log")}
