# `make fuzz` (scripts/fuzz.sh): the libFuzzer harnesses alone, built with clang. The readers
# (scene, glTF, and the JSON reader of scripts, lessons and settings) are compiled with the fuzzer's coverage instrumentation, ASan and UBSan; tinygltf
# and nlohmann come from Debian as they are. PENUMBRA_FUZZ_COVERAGE builds the same
# harnesses with source-based coverage instead, to replay a corpus for llvm-cov.
option(PENUMBRA_FUZZ_COVERAGE "harnesses with -fprofile-instr-generate, no fuzzing engine" OFF)
if(PENUMBRA_FUZZ_COVERAGE)
  set(FUZZ_COMPILE -fprofile-instr-generate -fcoverage-mapping -O1 -g)
  set(FUZZ_LINK -fprofile-instr-generate -fsanitize=fuzzer)
else()
  set(FUZZ_COMPILE -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -O1 -g)
  set(FUZZ_LINK -fsanitize=fuzzer,address,undefined)
endif()
add_library(penumbra_fuzz_scene STATIC
  app/base/input_error.cpp app/scene/scene.cpp app/scene/scene_file.cpp app/scene/scene_gltf.cpp
  app/scene/gltf_file_access.cpp app/scene/gltf_declared.cpp app/base/json_input.cpp app/io/output_path.cpp
  app/scene/mesh_builders.cpp app/scene/animation.cpp app/scene/gltf_animation.cpp
  app/scene/mesh_normals.cpp)
target_include_directories(penumbra_fuzz_scene PUBLIC app)
target_compile_definitions(penumbra_fuzz_scene PUBLIC GLM_FORCE_RADIANS)
target_compile_options(penumbra_fuzz_scene PUBLIC ${FUZZ_COMPILE})
target_link_libraries(penumbra_fuzz_scene PUBLIC glm::glm TinyGLTF::TinyGLTF nlohmann_json::nlohmann_json)
foreach(harness scene_json gltf script lesson settings)
  add_executable(fuzz_${harness} tests/fuzz/fuzz_${harness}.cpp)
  target_compile_definitions(fuzz_${harness} PRIVATE
    PENUMBRA_FUZZ_SEEDS="${CMAKE_SOURCE_DIR}/tests/fuzz/corpus")
  target_link_libraries(fuzz_${harness} PRIVATE penumbra_fuzz_scene)
  target_link_options(fuzz_${harness} PRIVATE ${FUZZ_LINK})
endforeach()
