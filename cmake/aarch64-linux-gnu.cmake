# CMake toolchain file for the board: 64-bit ARM Linux (Raspberry Pi 4/5 class).
#
# Two ways to use it (PLATFORM.md "Cross-building for the board"):
#  * Debian multiarch (CI, .ci/cross): the arm64 libraries are installed beside the amd64
#    ones under /usr/lib/aarch64-linux-gnu; nothing else to set.
#      cmake -S . -B build-aarch64 --toolchain cmake/aarch64-linux-gnu.cmake \
#            -DICACAM_HOST_TOOLS=OFF -DICACAM_BENCH=OFF
#  * A sysroot copied from the board (a real deployment links against the board's own
#    libraries, e.g. Raspberry Pi's libcamera fork). One command does the copy, the build
#    and the tests:  ICACAM_BOARD=pi@board bash .ci/cross   (docs/hardware.md). By hand:
#      cmake ... -DICACAM_SYSROOT=/opt/pi-sysroot   (or the environment variable, or
#      -DCMAKE_SYSROOT=/opt/pi-sysroot: the same)
# Tests run through qemu-aarch64-static (CMAKE_CROSSCOMPILING_EMULATOR), so ctest and
# gtest_discover_tests work on the build machine without binfmt_misc.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)

set(ICACAM_CROSS_PREFIX "aarch64-linux-gnu-" CACHE STRING "Prefix of the cross compiler")
set(CMAKE_C_COMPILER ${ICACAM_CROSS_PREFIX}gcc)
set(CMAKE_CXX_COMPILER ${ICACAM_CROSS_PREFIX}g++)

if(NOT DEFINED ICACAM_SYSROOT AND DEFINED ENV{ICACAM_SYSROOT})
    set(ICACAM_SYSROOT "$ENV{ICACAM_SYSROOT}")
endif()
if(NOT ICACAM_SYSROOT AND CMAKE_SYSROOT)
    set(ICACAM_SYSROOT "${CMAKE_SYSROOT}")
endif()
# try_compile projects re-read this file: pass the sysroot choice on to them.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES ICACAM_SYSROOT ICACAM_CROSS_PREFIX)

if(ICACAM_SYSROOT)
    set(CMAKE_SYSROOT "${ICACAM_SYSROOT}")
    set(CMAKE_FIND_ROOT_PATH "${ICACAM_SYSROOT}")
    set(_icacam_pc_root "${ICACAM_SYSROOT}")
else()
    set(_icacam_pc_root "")
endif()

# bookworm's pkgconf has no aarch64-linux-gnu-pkg-config: point the native one at the arm64
# .pc files only, and make it prefix paths with the sysroot when there is one.
set(ENV{PKG_CONFIG_LIBDIR}
    "${_icacam_pc_root}/usr/lib/aarch64-linux-gnu/pkgconfig:${_icacam_pc_root}/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")
if(ICACAM_SYSROOT)
    set(ENV{PKG_CONFIG_SYSROOT_DIR} "${ICACAM_SYSROOT}")
endif()

# Programs (cmake, python, qemu) come from the build machine; libraries, headers and CMake
# packages only from the target's side.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
if(NOT ICACAM_SYSROOT)
    # Multiarch: the "root" is / itself, and CMAKE_LIBRARY_ARCHITECTURE selects the arm64
    # folders; amd64 libraries under /usr/lib/x86_64-linux-gnu are not searched.
    set(CMAKE_FIND_ROOT_PATH "/")
endif()

find_program(ICACAM_QEMU_AARCH64 qemu-aarch64-static)
if(ICACAM_QEMU_AARCH64)
    if(ICACAM_SYSROOT)
        set(CMAKE_CROSSCOMPILING_EMULATOR "${ICACAM_QEMU_AARCH64};-L;${ICACAM_SYSROOT}")
    else()
        set(CMAKE_CROSSCOMPILING_EMULATOR "${ICACAM_QEMU_AARCH64}")
    endif()
endif()
