# SPDX-License-Identifier: Apache-2.0
# Cross build for arm64 with Debian's own cross toolchain and multiarch libraries:
#   apt-get install g++-aarch64-linux-gnu pkgconf:arm64 qemu-user <each -dev package>:arm64
#   cmake -S . -B build/arm64 -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake
# (tools/cross-arm64 does this and runs the tests). Libraries come from /usr/lib/aarch64-linux-gnu
# (multiarch: no sysroot), headers from /usr/include, arch-independent CMake packages (Catch2,
# Eigen, nlohmann-json) from /usr/lib/cmake and /usr/share. Tests run under qemu-user: CTest and
# Catch2's test discovery prefix CMAKE_CROSSCOMPILING_EMULATOR, and tests that start raysd, raysctl
# or ptu-sim as child processes prefix it too (this machine has no binfmt handler for arm64).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
# pkgconf:arm64's wrapper reads /usr/lib/aarch64-linux-gnu/pkgconfig.
set(PKG_CONFIG_EXECUTABLE aarch64-linux-gnu-pkg-config CACHE FILEPATH "pkg-config for arm64")
# The target's libraries only, never the build machine's (/usr/lib/x86_64-linux-gnu).
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
# The emulated programs load Debian's arm64 libc and libstdc++ from the multiarch paths (libc6:arm64
# and libstdc++6:arm64, which the :arm64 -dev packages bring: the libraries a rig runs), so qemu
# needs no -L prefix. Not -L /usr/aarch64-linux-gnu: its loader (libc6-arm64-cross, an older build
# of glibc 2.36) would load the multiarch libc.so.6 found first on the library path, and that
# mismatched pair hangs in pthread_create.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 CACHE STRING "Runs arm64 programs on the build machine")
