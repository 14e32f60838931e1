// `penumbra shaders --dump DIR`: the final source (every #include expanded, the defines
// prepended, as the driver receives it) of every program variant the pipeline can build,
// so that any GLSL compiler (the tests run glslangValidator) can check each one.
#pragma once
#include <filesystem>

// Writes DIR/NNNN-<source>.<vert|frag|comp> for the sources of program NNNN and
// DIR/programs.txt, one line per program: its number, its source files, its defines (on
// one line, ';' between them). DIR is created; files of an earlier dump there are replaced.
// Returns the number of programs. Throws InputError when DIR cannot be written.
int dumpShaderSources(const std::filesystem::path& directory);
