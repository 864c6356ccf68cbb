// softgl/config.h — what softgl's headers need from the compiler: C++20. Every public header includes it first,
// so that a translation unit compiled at an older language level stops here with one clear message instead of
// errors inside the templates. (CMake users get the level from the targets: softgl::softgl requires cxx_std_20.)
#pragma once

#if !defined(__cplusplus) || (__cplusplus < 202002L && !(defined(_MSVC_LANG) && _MSVC_LANG >= 202002L))
#error "softgl needs C++20 (-std=c++20 or later); in CMake, link softgl::softgl and do not force an older -std"
// #error lets the compiler go on; a missing header stops it, before the rest of softgl is parsed.
#include <softgl/stop-here-softgl-needs-cxx20>
#endif
