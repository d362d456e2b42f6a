#pragma once
/// @file Version of the numerical engine, set by CMake from project(VERSION).
#include <string_view>

namespace filmdyn {

/// FilmDyn's version string, e.g. "0.1.0".
std::string_view Version();

}  // namespace filmdyn
