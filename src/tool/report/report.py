#!/usr/bin/env python3
"""The page of a history folder: `crosscheck report HISTORY --out DIR` runs this.

Reads every record of HISTORY (one JSON file per run, written by `crosscheck campaign
--history` and, for a night of fuzzing, `crosscheck fuzz-history`) and writes DIR/index.html,
self-contained (plots as embedded PNG from matplotlib, case pictures as inline SVG from
`crosscheck triage --svg`): a header with the last campaign's commit, seed, versions and machine;
a grid of query kinds against parties in that campaign; trends over the runs; a card for each
finding group new in the last run (campaign or fuzzing); a ledger of known oracle_defect groups;
and the last night of fuzzing per target.
Exit status 0 written, 2 bad input (a record that is not one, named with the place)."""

import argparse
import base64
import io
import json
import os
import re
import subprocess
import sys
import tempfile

import jinja2
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FORMAT, VERSION = "crosscheck history", 1
# Classes a party can be blamed for, worst first, with the colours of the grid and plots.
CLASSES = [("impl_bug", "#c62828"), ("exact_defect", "#6a1b9a"), ("oracle_crash", "#ad1457"),
           ("oracle_defect", "#ef6c00"), ("out_of_contract", "#90a4ae")]
CLEAN = "#2e7d32"
MAX_CARDS = 24


class BadInput(Exception):
    pass


def load_records(folder):
    """Every record in the folder, oldest first; a file that is not a record is bad input."""
    records = []
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".json"):
            continue
        path = os.path.join(folder, name)
        try:
            with open(path, encoding="utf-8") as f:
                record = json.load(f)
        except json.JSONDecodeError as e:
            raise BadInput(f"{path}: line {e.lineno} column {e.colno}: {e.msg}")
        except (OSError, UnicodeDecodeError) as e:
            raise BadInput(f"{path}: {e}")
        if not isinstance(record, dict) or record.get("format") != FORMAT:
            raise BadInput(f'{path}: not a crosscheck history record (no "format": "{FORMAT}")')
        if record.get("version") != VERSION:
            raise BadInput(f"{path}: record version {record.get('version')!r}; this tool reads version {VERSION}")
        for key, kind in (("started", str), ("run", str), ("queries", dict), ("findings", list)):
            if not isinstance(record.get(key), kind):
                raise BadInput(f'{path}: "{key}" is missing or not a {kind.__name__}')
        record["_file"] = name
        records.append(record)
    if not records:
        raise BadInput(f"{folder}: no history records (*.json) in it")
    records.sort(key=lambda r: (r["started"], r["_file"]))
    return records


def load_known(path):
    """The ledger's links: [{"match": text in a group, "link": URL, "note": text}]."""
    if not path:
        return []
    try:
        with open(path, encoding="utf-8") as f:
            known = json.load(f)
    except json.JSONDecodeError as e:
        raise BadInput(f"{path}: line {e.lineno} column {e.colno}: {e.msg}")
    except OSError as e:
        raise BadInput(f"{path}: {e}")
    if not isinstance(known, list) or not all(isinstance(k, dict) and isinstance(k.get("match"), str) for k in known):
        raise BadInput(f'{path}: a list of {{"match": ..., "link": ..., "note": ...}} is expected')
    return known


def png(figure):
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=110, bbox_inches="tight")
    plt.close(figure)
    return "data:image/png;base64," + base64.b64encode(buffer.getvalue()).decode("ascii")


def run_label(record, i):
    return f"{i + 1}\n{record['started'][5:10]}"


def over_runs(figure, axes, records, ylabel, title, grid_axis="both", columns=1):
    """The figure's common frame: one tick per run, a grid, the legend beside it; as PNG."""
    axes.set_ylabel(ylabel)
    axes.set_xticks(range(len(records)), [run_label(r, i) for i, r in enumerate(records)], fontsize=7)
    axes.grid(alpha=0.3, axis=grid_axis)
    axes.legend(fontsize=7, ncol=columns, loc="upper left", bbox_to_anchor=(1.01, 1))
    axes.set_title(title, fontsize=10)
    return png(figure)


def plot_rates(records):
    figure, axes = plt.subplots(figsize=(7.5, 3.6))
    kinds = sorted({k for r in records if r["run"] == "campaign" for k in r["queries"]})
    xs = list(range(len(records)))
    for kind in kinds:
        ys = [r["queries"].get(kind, {}).get("cases_per_second") for r in records]
        points = [(x, y) for x, y in zip(xs, ys) if y]
        if points:
            axes.plot([p[0] for p in points], [p[1] for p in points], marker="o", label=kind)
    axes.set_yscale("log")
    return over_runs(figure, axes, records, "cases per second", "Cases per second, per query kind", columns=2)


def plot_classes(records):
    figure, axes = plt.subplots(figsize=(7.5, 3.2))
    xs = list(range(len(records)))
    bottom = [0] * len(records)
    for cls, colour in CLASSES:
        ys = [sum(q.get(cls, 0) for q in r["queries"].values()) for r in records]
        axes.bar(xs, ys, bottom=bottom, color=colour, label=cls)
        bottom = [b + y for b, y in zip(bottom, ys)]
    return over_runs(figure, axes, records, "cases", "Findings per class", grid_axis="y")


def plot_groups(records, new_per_run):
    figure, axes = plt.subplots(figsize=(7.5, 3.0))
    xs = list(range(len(records)))
    totals = [len(groups_of(r)) for r in records]
    new = [len(n) for n in new_per_run]
    axes.bar(xs, [t - n for t, n in zip(totals, new)], color="#78909c", label="known groups")
    axes.bar(xs, new, bottom=[t - n for t, n in zip(totals, new)], color="#d81b60", label="new groups")
    return over_runs(figure, axes, records, "finding groups", "Finding groups: new against known", grid_axis="y")


def plot_fuzz(records):
    fuzz = [r for r in records if r["run"] == "fuzz" and isinstance(r.get("targets"), dict)]
    if not fuzz:
        return None
    figure, (cov, rate) = plt.subplots(1, 2, figsize=(9, 3.0))
    for target in sorted({t for r in fuzz for t in r["targets"]}):
        ys = [r["targets"].get(target, {}) for r in fuzz]
        cov.plot(range(len(fuzz)), [y.get("coverage_after") for y in ys], marker="o", label=target)
        rate.plot(range(len(fuzz)), [y.get("execs_per_second") for y in ys], marker="o", label=target)
    for axes, title in ((cov, "Fuzz coverage (libFuzzer's cov, after merging)"), (rate, "Executions per second")):
        axes.set_xticks(range(len(fuzz)), [run_label(r, i) for i, r in enumerate(fuzz)], fontsize=7)
        axes.set_xlim(-0.5, len(fuzz) - 0.5)
        axes.set_xlabel("night", fontsize=8)
        axes.grid(alpha=0.3)
        axes.set_title(title, fontsize=10)
    rate.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1))
    return png(figure)


def groups_of(record):
    """The record's finding groups: group -> its findings."""
    groups = {}
    for f in record["findings"]:
        groups.setdefault(f.get("group") or f.get("what", "?"), []).append(f)
    return groups


def grid_of(record, all_records):
    """Rows: the run's kinds; columns: 'library' and every party blamed in any run."""
    parties = sorted({p for r in all_records for f in r["findings"] for p in f.get("parties", {})} - {"library"})
    parties = ["library"] + parties
    rows = []
    for kind in sorted(record["queries"]):
        cells = []
        for party in parties:
            found = [f for f in record["findings"] if f["query"] == kind and party in f.get("parties", {})]
            counts = {}
            for f in found:
                counts[f["class"]] = counts.get(f["class"], 0) + 1
            worst = next(((c, colour) for c, colour in CLASSES if c in counts), None)
            cells.append({"party": party, "counts": counts, "total": len(found),
                          "colour": worst[1] if worst else CLEAN, "anchor": f"f-{kind}-{party}" if found else None})
        rows.append({"kind": kind, "cases": record["queries"][kind].get("cases", 0), "cells": cells})
    return parties, rows


def scalable(svg):
    """The SVG with a viewBox from its width and height, so that it scales to its card."""
    match = re.match(r'\s*<svg([^>]*?)\swidth="([\d.]+)"\s+height="([\d.]+)"', svg)
    if not match or "viewBox" in svg[:match.end()]:
        return svg
    return svg[:match.start(2) - 7] + f' viewBox="0 0 {match.group(2)} {match.group(3)}"' + svg[match.end(3) + 1:]


def defect_of(group):
    """A group's defect: its key without the coarse features and the margin's decade, which
    tell cases of one defect apart."""
    return " ".join(t for t in group.split() if t not in ("touching", "parallel", "degenerate", "crash")
                    and not re.fullmatch(r"1e-?\d+", t))


def new_groups_per_run(records):
    """Per run, the groups of its findings that no earlier run had, in the order first met."""
    seen, new_per_run = set(), []
    for r in records:
        groups = groups_of(r)
        new_per_run.append([g for g in groups if g not in seen])
        seen.update(groups)
    return new_per_run


def cards_order(new, groups):
    """The new groups, the worst class first; within a class, those with a stored case (a picture
    to look at), then the most often met."""
    severity = {cls: i for i, (cls, _) in enumerate(CLASSES)}
    return sorted(new, key=lambda g: (severity.get(groups[g][0]["class"], len(CLASSES)),
                                      not any(f.get("case_file") for f in groups[g]), -len(groups[g]), g))


def ledger_of(records, known):
    """One row per defect of another library (its oracle_defect groups taken together over
    features and margins): first and last run met, runs, groups, findings, and its link."""
    defects = {}
    for r in records:
        for g, found in groups_of(r).items():
            if found[0]["class"] != "oracle_defect":
                continue
            d = defects.setdefault(defect_of(g), {"query": found[0]["query"], "first": r["started"], "runs": set(),
                                                  "groups": set(), "findings": 0})
            d["last"] = r["started"]
            d["runs"].add(r["_file"])
            d["groups"].add(g)
            d["findings"] += len(found)
    ledger = []
    for defect, d in sorted(defects.items(), key=lambda item: (item[1]["query"], item[0])):
        link = next((k for k in known if k["match"] in defect), None)
        ledger.append({"defect": defect, "query": d["query"], "first": d["first"], "last": d["last"],
                       "times": len(d["runs"]), "groups": len(d["groups"]), "findings": d["findings"],
                       "link": link.get("link") if link else None, "note": link.get("note") if link else None})
    return ledger


def triage(crosscheck, case_file):
    """The case's picture (inline SVG) and what triage says of it, or Nones."""
    if not crosscheck or not case_file or not os.path.isfile(case_file):
        return None, None
    with tempfile.TemporaryDirectory() as scratch:
        svg_path = os.path.join(scratch, "case.svg")
        run = subprocess.run([crosscheck, "triage", "--svg", svg_path, case_file], capture_output=True, text=True,
                             timeout=120)
        svg = None
        if os.path.isfile(svg_path):
            with open(svg_path, encoding="utf-8") as f:
                svg = f.read()
            if svg.startswith("<?xml"):
                svg = svg[svg.index("?>") + 2:]
            svg = scalable(svg)
    return svg, run.stdout.strip() or None


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--history", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--crosscheck", default="")
    parser.add_argument("--known", default="")
    args = parser.parse_args()
    try:
        records = load_records(args.history)
        known = load_known(args.known)
    except BadInput as e:
        print(f"crosscheck report: {e}", file=sys.stderr)
        return 2

    new_per_run = new_groups_per_run(records)

    last = records[-1]
    campaigns = [r for r in records if r["run"] == "campaign"]
    latest = campaigns[-1] if campaigns else last
    nights = [r for r in records if r["run"] == "fuzz"]
    parties, rows = grid_of(latest, records)
    cards = []
    latest_groups = groups_of(last)
    for g in cards_order(new_per_run[-1], latest_groups)[:MAX_CARDS]:
        found = latest_groups[g]
        stored = next((f for f in found if f.get("case_file")), found[0])
        svg, said = triage(args.crosscheck, stored.get("case_file"))
        cards.append({"group": g, "query": stored["query"], "cls": stored["class"], "what": stored.get("what", ""),
                      "disagreement": stored.get("disagreement"), "run": last["run"],
                      "parties": stored.get("parties", {}), "margin": stored.get("margin"), "count": len(found),
                      "case_file": stored.get("case_file"), "svg": svg, "triage": said,
                      "colour": dict(CLASSES).get(stored["class"], CLEAN)})
    ledger = ledger_of(records, known)

    findings_by_cell = {}
    for f in latest["findings"]:
        for p in f.get("parties", {}):
            findings_by_cell.setdefault(f"f-{f['query']}-{p}", []).append(f)

    environment = jinja2.Environment(loader=jinja2.FileSystemLoader(os.path.dirname(os.path.abspath(__file__))),
                                     autoescape=jinja2.select_autoescape(["html", "j2"]))
    page = environment.get_template("page.html.j2").render(
        latest=latest, last=last, night=nights[-1] if nights else None, runs=len(records),
        first_run=records[0]["started"], parties=parties, rows=rows,
        classes=CLASSES, clean=CLEAN, cards=cards, more_cards=max(0, len(new_per_run[-1]) - MAX_CARDS),
        ledger=ledger, findings_by_cell=findings_by_cell,
        plots={"rates": plot_rates(records), "classes": plot_classes(records),
               "groups": plot_groups(records, new_per_run), "fuzz": plot_fuzz(records)})
    os.makedirs(args.out, exist_ok=True)
    target = os.path.join(args.out, "index.html")
    with tempfile.NamedTemporaryFile("w", encoding="utf-8", dir=args.out, delete=False, suffix=".tmp") as f:
        f.write(page)
    os.chmod(f.name, 0o644)
    os.replace(f.name, target)
    print(target)
    return 0


if __name__ == "__main__":
    sys.exit(main())
