"""Medians over the rounds of bench/trace-records/run.sh (or another folder of the same kind of
files, bench/trace-variants): per file kind, side, column and shaders."""
import glob, re, statistics, sys
from collections import defaultdict

out = sys.argv[1] if len(sys.argv) > 1 else "bench/trace-records"
values = defaultdict(list)
for path in sorted(glob.glob(f"{out}/*-r*.md")):
    kind, shaders = re.match(r".*/(\w+)-(\w+)-r\w+\.md", path).groups()
    rows = [l for l in open(path) if l.startswith("| ")]
    header = [c.strip() for c in rows[0].split("|")]
    for row in rows[1:]:
        cells = dict(zip(header, [c.strip() for c in row.split("|")]))
        for column in ("run ms", "trace ms", "classify ms", "light_layers ms", "minmax ms", "nbuffer ms",
                       "filter ms", "composite ms", "gbuffer ms", "trace.fetches",
                       "fetches / searched ray"):
            if cells.get(column, "-") != "-":
                values[(kind, cells["side"], column, shaders)].append(float(cells[column]))
for key in sorted(values):
    v = values[key]
    print(*key, f"median {statistics.median(v):.2f} of {len(v)}: " + ", ".join(f"{x:g}" for x in v), sep=" | ")
