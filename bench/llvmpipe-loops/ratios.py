#!/usr/bin/env python3
"""After / before per side of a folder of cube-{before,after}-rN.md files (run.sh here, or
bench/llvmpipe-writes/run.sh): the medians over the rounds of the run and of each stage,
the best round, and the median of the per-round ratios after / before."""
import glob, re, statistics, sys

def table(path):
    rows = [l for l in open(path) if l.startswith("| ")]
    header = [c.strip() for c in rows[0].split("|")]
    return {d["side"]: d for d in (dict(zip(header, [c.strip() for c in r.split("|")])) for r in rows[1:])}

for folder in sys.argv[1:]:
    rounds = sorted({int(re.search(r"-r(\d+)\.md", f).group(1)) for f in glob.glob(f"{folder}/cube-after-r*.md")})
    after = [table(f"{folder}/cube-after-r{r}.md") for r in rounds]
    before = [table(f"{folder}/cube-before-r{r}.md") for r in rounds]
    print(f"## {folder} ({len(rounds)} rounds)\n")
    print("| side | after ms (best) | before ms | after / before | stages, after / before |\n|---|---|---|---|---|")
    for side in after[0]:
        cells = []
        for column in [c for c in after[0][side] if c.endswith(" ms")]:
            a = [float(t[side][column]) for t in after]
            b = [float(t[side][column]) for t in before]
            if statistics.median(b) == 0:
                continue
            ratio = statistics.median([x / y for x, y in zip(a, b)])
            if column == "run ms":
                run = f"| {side} | {statistics.median(a):.1f} ({min(a):.1f}) | {statistics.median(b):.1f} | {ratio:.3f} |"
            elif statistics.median(b) >= 0.1:
                cells.append(f"{column[:-3]} {ratio:.2f}")
        print(run + " " + ", ".join(cells) + " |")
    print()
