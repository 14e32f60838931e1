#!/bin/sh
# Issue 14, session 6: the trace with its step records compiled out (TRACE_RECORDING 0 in
# shaders/shared/trace_ray.glsl; the shaders of commit cf71058), against the shaders before
# it (commit f53a80a: the records' branches compiled in, checked at run time), and what the
# rest of the trace costs once the search is taken out. Both sides run on the same binary,
# their shaders swapped in with PENUMBRA_SHADER_DIR (f53a80a's ignore the TRACE_RECORDING
# define; cf71058's ignore the later specialization defines). Processes alternate
# before / after, three rounds; within a process the sides alternate frame by frame.
# Run on a quiet machine from the repository root after building:
#   sh bench/trace-records/run.sh
BEFORE=f53a80a AFTER=cf71058
OUT=${OUT:-bench/trace-records}
. scripts/ab_shaders.sh
# Ablations of the `after` shaders (timing only; their images are wrong on purpose):
#  no_search: every searched ray gets a constant answer instead of its search;
#  no_early_outs: as no_search, and the inside and region early outs are skipped too;
#  empty: every invocation returns at once (dispatch, clears, the list).
python3 - "$TMP" <<'PY'
import shutil, sys
tmp = sys.argv[1]
def variant(name, edits):
    shutil.copytree(f"{tmp}/after", f"{tmp}/{name}")
    for path, old, new in edits:
        p = f"{tmp}/{name}/{path}"
        text = open(p).read()
        assert old in text, (name, old)
        open(p, "w").write(text.replace(old, new))
no_search = ("shared/trace_pixel.glsl", "    bool blocked = search == SEARCH_HIERARCHICAL",
             "    bool blocked = (gIterations & 1u) != 0u; if (false) blocked = search == SEARCH_HIERARCHICAL")
variant("no_search", [no_search])
variant("no_early_outs", [no_search,
    ("shared/trace_pixel.glsl", "    if (trace.switches.y != 0 && !endKept", "    if (false && !endKept"),
    ("shared/trace_pixel.glsl", "(trace.switches.z != 0 && regionIsEmpty", "(false && regionIsEmpty"),
    ("shared/trace_pixel.glsl", "    if (trace.switches.y != 0 && endKept &&", "    if (false && endKept &&")])
variant("empty", [("trace.comp", "  if (pixel.x < 0) return;\n", "  if (pixel.x < 0 || trace.config.x > 0) return;\n")])
PY
before_after_rounds
for round in 1 2; do
  for side in after no_search no_early_outs empty; do
    dragon $side 2048 a$round
  done
done
