# A CMake toolchain file for 64-bit ARM (aarch64) on Debian, from an x86-64 machine:
#
#   dpkg --add-architecture arm64 && apt-get update
#   apt-get install g++-aarch64-linux-gnu qemu-user-static libassimp-dev:arm64 libjpeg62-turbo-dev:arm64 \
#     libwebp-dev:arm64 libstb-dev:arm64 zlib1g-dev:arm64 libglm-dev catch2 libcli11-dev
#   cmake -S . -B build/arm64 -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake -DCMAKE_BUILD_TYPE=Release
#
# (scripts/arm64.sh does all of it.) Debian's multiarch layout puts the arm64 libraries beside the host's, under
# /usr/lib/aarch64-linux-gnu, and the header-only packages (GLM, Catch2, CLI11) serve both. The test programs run
# under qemu-aarch64-static (CMAKE_CROSSCOMPILING_EMULATOR), so ctest and Catch2's test discovery work as on the
# host.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

# Libraries and CMake packages of the target architecture only: the host's x86-64 ones sit in the same /usr.
set(CMAKE_IGNORE_PATH /usr/lib/x86_64-linux-gnu /usr/lib/x86_64-linux-gnu/cmake /lib/x86_64-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)

# pkg-config (libwebp for softgl-render's animations) reads the arm64 .pc files, not the host's.
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")

find_program(SOFTGL_QEMU_AARCH64 qemu-aarch64-static qemu-aarch64)
if(SOFTGL_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${SOFTGL_QEMU_AARCH64})
endif()
