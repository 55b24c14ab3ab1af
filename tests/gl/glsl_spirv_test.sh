#!/usr/bin/env bash
# The GLSL library compiles as GLSL 3.30 core and GLSL ES 3.00 (so it uses
# nothing beyond them), to Vulkan SPIR-V, and spirv-cross translates that to
# HLSL (shader model 5.0) and MSL without errors.
# Usage: glsl_spirv_test.sh SKYBAKE_GLSL_PRINT WORK_DIR
set -u
print=$1
work=$2
mkdir -p "$work"
passed=0
failed=0
check() {
  local name=$1
  shift
  if "$@" >"$work/$name.log" 2>&1; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "glsl_spirv: $name failed:"
    cat "$work/$name.log"
  fi
}
"$print" 330 >"$work/sky_330.frag"
"$print" 300es >"$work/sky_300es.frag"
"$print" 450 >"$work/sky_450.frag"
check glsl_330 glslangValidator -S frag "$work/sky_330.frag"
check glsl_300es glslangValidator -S frag "$work/sky_300es.frag"
check spirv_vulkan glslangValidator -S frag -V -o "$work/sky.spv" "$work/sky_450.frag"
check hlsl spirv-cross "$work/sky.spv" --hlsl --shader-model 50 --output "$work/sky.hlsl"
check msl spirv-cross "$work/sky.spv" --msl --output "$work/sky.metal"
echo "glsl_spirv: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
