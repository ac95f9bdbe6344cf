#pragma once
// Number formatting shared by the tests that record measured values (RecordProperty).
#include <cstdio>
#include <string>

namespace adcs::test {

//! v in scientific notation with 4 significant digits ("1.234e-05").
inline std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", v);
  return buf;
}

}  // namespace adcs::test
