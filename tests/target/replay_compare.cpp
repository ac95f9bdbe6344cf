// Compares a host replay with a target replay (replay_runtime.hpp output format) and prints the
// largest relative difference. Usage:
//   replay_compare <host.txt> <target.txt> <steps> <tolerance>
// Passes (exit 0) when both files are complete (header, exactly <steps> step lines, "# done"),
// have the same columns, every exact column (scale 0: statuses, counters) is equal, and every
// other value satisfies |host - target| <= tolerance * max(|host|, scale of its column).
// Also reports how many values are bit-identical.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Replay {
  std::vector<std::string> names;
  std::vector<double> scales;
  std::vector<std::vector<std::string>> rows;  // tokens of each step line (k first)
  bool done = false;
  std::string error;
};

Replay load(const char* path) {
  Replay r;
  std::ifstream in(path);
  if (!in) {
    r.error = std::string("cannot read ") + path;
    return r;
  }
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# columns", 0) == 0) {
      std::istringstream ss(line.substr(line.find(' ', 2) + 1));
      std::string tok;
      while (ss >> tok) {
        const std::size_t colon = tok.rfind(':');
        r.names.push_back(tok.substr(0, colon));
        r.scales.push_back(std::strtod(tok.c_str() + colon + 1, nullptr));
      }
    } else if (line.rfind("# done", 0) == 0) {
      r.done = true;
    } else if (line.rfind("# error", 0) == 0) {
      r.error = line;
    } else if (!line.empty() && line[0] != '#') {
      std::istringstream ss(line);
      std::vector<std::string> toks;
      std::string tok;
      while (ss >> tok)
        if (tok.find('=') == std::string::npos) toks.push_back(tok);  // cost fields are not outputs
      r.rows.push_back(toks);
    }
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: replay_compare <host.txt> <target.txt> <steps> <tolerance>\n");
    return 2;
  }
  const Replay h = load(argv[1]), t = load(argv[2]);
  const std::size_t steps = std::strtoul(argv[3], nullptr, 10);
  const double tol = std::strtod(argv[4], nullptr);
  int failures = 0;
  auto check = [&](bool ok, const std::string& what) {
    if (!ok) {
      std::printf("FAIL: %s\n", what.c_str());
      ++failures;
    }
    return ok;
  };
  check(h.error.empty(), "host: " + h.error);
  check(t.error.empty(), "target: " + t.error);
  check(h.done && t.done, "a replay did not finish (no '# done' line)");
  check(h.rows.size() == steps, "host has " + std::to_string(h.rows.size()) + " step lines, expected " +
                                    std::to_string(steps));
  check(t.rows.size() == steps, "target has " + std::to_string(t.rows.size()) + " step lines, expected " +
                                    std::to_string(steps));
  if (!check(!h.names.empty() && h.names == t.names && h.scales == t.scales, "column headers differ"))
    return 1;
  const std::size_t ncol = h.names.size();
  double max_rel = 0.0;
  std::size_t max_k = 0, max_c = 0, values = 0, identical = 0;
  std::vector<double> col_max(ncol, 0.0);
  for (std::size_t k = 0; k < std::min(h.rows.size(), t.rows.size()); ++k) {
    const auto& a = h.rows[k];
    const auto& b = t.rows[k];
    if (!check(a.size() == ncol && b.size() == ncol, "step line " + std::to_string(k) + " has the wrong field count"))
      continue;
    for (std::size_t c = 0; c < ncol; ++c) {
      if (h.scales[c] == 0.0) {  // exact column (also the step index k)
        check(a[c] == b[c], "step " + std::to_string(k) + " " + h.names[c] + ": host " + a[c] + ", target " + b[c]);
        continue;
      }
      const double x = std::strtod(a[c].c_str(), nullptr), y = std::strtod(b[c].c_str(), nullptr);
      ++values;
      if (a[c] == b[c]) {
        ++identical;
        continue;
      }
      const double rel = std::abs(x - y) / std::max(std::abs(x), h.scales[c]);
      if (!(rel <= tol))
        check(false, "step " + std::to_string(k) + " " + h.names[c] + ": host " + a[c] + ", target " + b[c] +
                         ", relative difference " + std::to_string(rel));
      if (!(rel <= max_rel)) {
        max_rel = rel;
        max_k = k;
        max_c = c;
      }
      col_max[c] = std::max(col_max[c], rel);
    }
  }
  std::printf("compared %zu steps, %zu floating-point values: %zu bit-identical (%.2f%%)\n", h.rows.size(), values,
              identical, values ? 100.0 * double(identical) / double(values) : 100.0);
  if (max_rel > 0.0)
    std::printf("max relative difference %.3g (step %zu, column %s; tolerance %.3g)\n", max_rel, max_k,
                h.names[max_c].c_str(), tol);
  else
    std::printf("max relative difference 0: bit-identical (tolerance %.3g)\n", tol);
  for (std::size_t c = 0; c < ncol; ++c)
    if (col_max[c] > 0.0) std::printf("  %-14s max relative difference %.3g\n", h.names[c].c_str(), col_max[c]);
  std::printf("max_rel_diff=%.17g bit_identical=%s\n", max_rel, identical == values ? "yes" : "no");
  return failures ? 1 : 0;
}
