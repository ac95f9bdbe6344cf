#pragma once
// How often each step() status was returned over a run (fault scenarios report them all, so a
// reader sees what the controller said while its inputs were bad).
#include <cstddef>
#include <string>

#include "adcs/core/status.hpp"
#include "scenarios/scenario.hpp"

namespace adcs::sim {

class StatusCounts {
 public:
  void add(Status s) noexcept { ++n_[static_cast<std::size_t>(s)]; }
  long count(Status s) const noexcept { return n_[static_cast<std::size_t>(s)]; }

  //! One metric per status, `steps_<name>` (zeros included: the absence of a status is a result).
  void to_metrics(RunResult& r) const {
    for (Status s : kAll) r.metrics.push_back({std::string("steps_") + to_string(s), double(count(s))});
  }
  //! "ok 2980, non_finite_input 20" (the statuses that occurred).
  std::string summary() const {
    std::string out;
    for (Status s : kAll)
      if (count(s) > 0) out += (out.empty() ? "" : ", ") + std::string(to_string(s)) + " " + std::to_string(count(s));
    return out;
  }

 private:
  static constexpr Status kAll[] = {Status::ok,          Status::non_finite_input, Status::out_of_range,
                                    Status::singular,    Status::ill_conditioned,  Status::constraint_violated,
                                    Status::saturated,   Status::not_converged,    Status::invalid_parameter,
                                    Status::request_not_met};
  long n_[sizeof(kAll) / sizeof(kAll[0])] = {};
};

}  // namespace adcs::sim
