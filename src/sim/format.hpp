#pragma once
// printf-style formatting into a std::string, for the claim texts, tags and notes of the ground
// code (one helper: the scenarios had five copies, which a unity batch would have merged).
#include <cstdio>
#include <string>

namespace adcs::sim {

template <class... Args>
std::string fmt(const char* format, Args... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

}  // namespace adcs::sim
