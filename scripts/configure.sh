#!/usr/bin/env bash
# Configures a build folder with the Ninja generator: scripts/configure.sh FOLDER [CMAKE ARGUMENTS...], from the
# repository's root. Ninja starts a target's compilations before the libraries it links are finished, so the slowest
# unit of the library no longer leaves a core idle. A folder configured earlier by another generator is made
# afresh (CMake cannot change the generator of a folder in place).
set -euo pipefail
dir=$1
shift
if [ -f "$dir/CMakeCache.txt" ] && ! grep -qx 'CMAKE_GENERATOR:INTERNAL=Ninja' "$dir/CMakeCache.txt"; then
  echo "softgl: $dir was configured by another CMake generator; configuring it afresh with Ninja"
  rm -rf "$dir"
fi
cmake -G Ninja -S . -B "$dir" "$@"
