#!/usr/bin/env python3
"""The table of the unit-cost scripts (bench/llvmpipe-writes/unit_costs.sh,
bench/llvmpipe-reads/unit_costs.sh): per stub, the median over its rounds of one stage's
time in the bench-compare files DIR/STUB-ROUND.md, and that median minus the baseline
stub's (with --per N, also divided by N, the reads per pixel of each stub).
Writes OUT as Markdown and prints it."""
import argparse, glob, statistics

parser = argparse.ArgumentParser()
parser.add_argument("--dir", required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--column", required=True, help='the stage column, e.g. "trace ms"')
parser.add_argument("--baseline", required=True, help="the stub the others are measured against")
parser.add_argument("--title", required=True, help="the first column's heading")
parser.add_argument("--per", type=int, default=0, help="reads per pixel of each stub")
parser.add_argument("stubs", nargs="+")
args = parser.parse_args()

def stage_ms(path):
    rows = [l for l in open(path) if l.startswith("| ")]
    header = [c.strip() for c in rows[0].split("|")]
    return float(dict(zip(header, [c.strip() for c in rows[1].split("|")]))[args.column])

ms = {s: [stage_ms(p) for p in sorted(glob.glob(f"{args.dir}/{s}-*.md"))] for s in args.stubs}
base = statistics.median(ms[args.baseline])
per = " per read |" if args.per else ""
with open(args.out, "w") as f:
    f.write(f"| {args.title} | {args.column}, median | minus {args.baseline} |{per} rounds |\n")
    f.write("|---" * (4 + (1 if args.per else 0)) + "|\n")
    for s in sorted(args.stubs, key=lambda s: statistics.median(ms[s])):
        m = statistics.median(ms[s])
        extra = f" {(m - base) / args.per:.2f} |" if args.per else ""
        f.write(f"| {s} | {m:.2f} | {m - base:.2f} |{extra} " + ", ".join(f"{x:g}" for x in ms[s]) + " |\n")
print(open(args.out).read())
