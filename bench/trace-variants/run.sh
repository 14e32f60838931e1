#!/bin/sh
# Issue 14, session 6: the trace and classify programs specialized per hierarchy and search
# (TRACE_HIERARCHY, TRACE_SEARCH in shaders/shared/trace_ray.glsl; CLASSIFY_OVER_MINMAX in
# shaders/classify.comp; the shaders of commit 203c9b2), against the shaders before it
# (commit cf71058: every hierarchy and search compiled into one program, chosen at run time;
# the step records already compiled out). Both sides run on the same binary, their shaders
# swapped in with PENUMBRA_SHADER_DIR (cf71058's ignore the new defines and read the same
# parameter block).
# Processes alternate before / after, three rounds; within a process the sides alternate
# frame by frame. Run on a quiet machine from the repository root after building:
#   sh bench/trace-variants/run.sh && python3 bench/trace-records/summary.py bench/trace-variants
BEFORE=cf71058 AFTER=203c9b2
OUT=${OUT:-bench/trace-variants}
. scripts/ab_shaders.sh
before_after_rounds
