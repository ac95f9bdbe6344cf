// libFuzzer harness, seed 003: PrescribedTimeSe3 (BsPdTC) and FtsmcSe3 on SE(3), each followed
// by the sat → Q chain (saturate_then_quantize), and the CompositeQuantizer<6> on its own with
// the seed 003 channels or fuzzed channel parameters. Input format: fuzz_common.hpp; first byte
// = target, second = configuration.
//
// Asserted on every step (besides "no crash, no sanitizer report"):
//  - the wrench command u is finite, whatever the status;
//  - a non-finite input gives exactly non_finite_input;
//  - a non-ok step outputs the failure command (zero wrench), keeps the last applied command and
//    leaves ψ̂ and the logged terms (PTC) or the sliding variable (FTSMC) bitwise unchanged; an
//    applied step keeps ψ̂ finite and >= 0 and, when asked for, reports the same terms / sliding
//    variable in its diagnostics as the accessors;
//  - quantizer: non-finite input / invalid channels leave u_q, the transmission mask and every
//    counter untouched; an applied call has |Q(u) − u| <= ϖ per channel, counts exactly the
//    channels whose level changed (mask bits = per-channel counters = total), is odd on the
//    logarithmic range, and sat → Q → clip stays within the limits and reports saturated exactly
//    when sat clipped.
#include <array>
#include <bitset>
#include <cstdint>

#include "adcs/actuator/quantizer.hpp"
#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/math/so3.hpp"
#include "fuzz_common.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

// File-local, and named: the five harnesses are compiled in one unit (tests/fuzz/CMakeLists.txt).
namespace ADCS_UNITY_ID {
using adcs::Status;
using adcs::Vec3;
using adcs::Vec6;
using Quantizer = adcs::CompositeQuantizer<6>;
constexpr int kMaxSteps = 10;

struct Scenario {
  adcs::Se3ScenarioParams sp;
  adcs::Se3SpacecraftState chaser[4];
  adcs::Se3DesiredState desired;
  Vec6 limit;
  Scenario() {
    adcs::Se3SpacecraftState target;
    FUZZ_CHECK(adcs::se3_target_initial_state(sp, target) == Status::ok, "set-up: target state");
    for (int i = 0; i < 4; ++i) chaser[i] = adcs::se3_chaser_initial_state(target, adcs::kSe3InitialPoses[i]);
    const adcs::Se3Spacecraft target_model(adcs::se3_target_params(sp));
    FUZZ_CHECK(adcs::se3_desired_state(target_model, target, sp, desired) == Status::ok, "set-up: desired state");
    limit = adcs::se3_actuator_limits(sp);
  }
};
const Scenario& scenario() {
  static const Scenario s;
  return s;
}

struct QuantizerSnapshot {
  Vec6 last;
  std::array<std::uint64_t, 6> per_channel;
  std::uint64_t total;
  explicit QuantizerSnapshot(const Quantizer& q)
      : last(q.last_output()), per_channel(q.channel_transmissions()), total(q.transmissions()) {}
  bool operator==(const QuantizerSnapshot& o) const {
    return fuzz::same_bits_mat(last, o.last) && per_channel == o.per_channel && total == o.total;
  }
};

//! u_c = clip(Q(sat(u))) with the documented outcome; `who` names the caller in messages.
void check_sat_quantize(const Vec6& u, const Vec6& limit, Quantizer& q) {
  Vec6 u_c = Vec6::Constant(-7.0);
  const Vec6 u_c0 = u_c;
  std::uint32_t mask = 0xdeadbeef;
  const QuantizerSnapshot before(q);
  const Status s = adcs::saturate_then_quantize<6>(u, limit, q, u_c, &mask);
  fuzz::stat(3, "saturate_then_quantize", s);
  const bool u_finite = fuzz::finite(u);
  fuzz::check_status_vs_input(s, u_finite, "saturate_then_quantize: non-finite input not rejected");
  if (!fuzz::applied(s)) {
    FUZZ_CHECK(fuzz::same_bits_mat(u_c, u_c0) && mask == 0xdeadbeef && QuantizerSnapshot(q) == before,
               "saturate_then_quantize: rejected but changed an output or a counter");
    return;
  }
  FUZZ_CHECK(fuzz::finite(u_c), "saturate_then_quantize: non-finite u_c");
  bool clipped = false;
  for (int i = 0; i < 6; ++i) {
    if (limit(i) > 0.0) {
      FUZZ_CHECK(std::fabs(u_c(i)) <= limit(i), "saturate_then_quantize: u_c beyond its limit");
      clipped = clipped || std::fabs(u(i)) > limit(i);
    }
  }
  FUZZ_CHECK((s == Status::saturated) == clipped, "saturate_then_quantize: saturated flag wrong");
  FUZZ_CHECK(QuantizerSnapshot(q).total == before.total + std::bitset<32>(mask).count(),
             "saturate_then_quantize: transmissions do not match the mask");
}

//! Q(u) with the documented outcome and the invariants of quantizer.hpp.
void check_apply(const Vec6& u, Quantizer& q) {
  Vec6 u_q = Vec6::Constant(-7.0);
  const Vec6 u_q0 = u_q;
  std::uint32_t mask = 0xdeadbeef;
  const QuantizerSnapshot before(q);
  const Status s = q.apply(u, u_q, &mask);
  fuzz::stat(2, "CompositeQuantizer", s);
  if (q.status() != Status::ok) {
    FUZZ_CHECK(s == Status::invalid_parameter, "CompositeQuantizer: invalid channels not reported");
  } else {
    fuzz::check_status_vs_input(s, fuzz::finite(u), "CompositeQuantizer: non-finite input not rejected");
  }
  const QuantizerSnapshot after(q);
  if (s != Status::ok) {
    FUZZ_CHECK(fuzz::same_bits_mat(u_q, u_q0) && mask == 0xdeadbeef && after == before,
               "CompositeQuantizer: rejected but changed an output or a counter");
    return;
  }
  FUZZ_CHECK(fuzz::finite(u_q) && fuzz::same_bits_mat(u_q, after.last), "CompositeQuantizer: bad u_q");
  std::uint64_t sum = 0;
  for (int i = 0; i < 6; ++i) {
    const auto& ch = q.channel(i);
    FUZZ_CHECK(std::fabs(u_q(i) - u(i)) <= ch.error_bound(), "CompositeQuantizer: |Q(u) - u| > error bound");
    const std::uint64_t d = after.per_channel[static_cast<std::size_t>(i)] - before.per_channel[static_cast<std::size_t>(i)];
    FUZZ_CHECK(d == ((mask >> i) & 1u), "CompositeQuantizer: mask bit and channel counter disagree");
    FUZZ_CHECK((d == 1) == (before.total == 0 || !(u_q(i) == before.last(i))),
               "CompositeQuantizer: transmission without a level change (or the reverse)");
    sum += d;
    if (std::fabs(u(i)) <= ch.params().u_s)
      FUZZ_CHECK(ch.quantize(-u(i)) == -ch.quantize(u(i)), "QuantizerChannel: Q_log not odd");  // ±0 equal
  }
  FUZZ_CHECK(after.total == before.total + sum, "CompositeQuantizer: total != sum of channels");
}

void fuzz_quantizer(int config, fuzz::Reader& r) {
  adcs::CompositeQuantizerParams<6> p = adcs::seed003_quantizer_params();
  if (config & 4) {  // fuzzed channels: validation, level tables at their limits
    for (auto& ch : p.channel) {
      if (r.u8() & 1) continue;
      ch.rho = r.value();
      ch.u_min = r.value();
      ch.u_s = r.value();
      ch.sigma = r.value();
    }
  }
  Quantizer q(p);
  q.reset();
  const Scenario& sc = scenario();
  for (int k = 0; k < kMaxSteps && !r.empty(); ++k) {
    const Vec6 u = r.vec<6>();
    if (r.u8() & 1)
      check_apply(u, q);
    else
      check_sat_quantize(u, (config & 8) ? Vec6(r.vec<6>()) : sc.limit, q);
  }
}

//! A state near `x0`: rotation by a fuzzed rotation vector (or, with `raw`, additive entries that
//! break orthonormality), fuzzed position and rate offsets.
adcs::Se3SpacecraftState perturbed(const adcs::Se3SpacecraftState& x0, bool raw, fuzz::Reader& r) {
  adcs::Se3SpacecraftState x = x0;
  x.C_NB = x0.C_NB * adcs::so3_exp(r.vec<3>());
  if (raw)
    for (int j = 0; j < 3; ++j) x.C_NB.col(j) += r.vec<3>();
  x.R_N += r.vec<3>();
  x.omega_BN_B += r.vec<3>();
  x.v_B += r.vec<3>();
  return x;
}

template <class Law>
void fuzz_law(int which, int config, fuzz::Reader& r) {
  const Scenario& sc = scenario();
  static const adcs::PrescribedTimeSe3 ptc_proto([] {
    adcs::PrescribedTimeSe3Params p;  // spec Table 1 gains
    p.zeta = adcs::quantization_compensation_gain(adcs::seed003_quantizer_params());  // ζ = 1.05 ϖ
    p.nominal = adcs::se3_chaser_nominal_params(scenario().sp);
    return p;
  }());
  static const adcs::FtsmcSe3 ftsmc_proto([] {
    adcs::FtsmcSe3Params p;
    p.nominal = adcs::se3_chaser_nominal_params(scenario().sp);
    return p;
  }());
  Law law = [&]() -> Law {
    if constexpr (std::is_same_v<Law, adcs::PrescribedTimeSe3>) return ptc_proto;
    else return ftsmc_proto;
  }();
  Quantizer q(adcs::seed003_quantizer_params());
  const bool raw = (config & 4) != 0;
  const bool with_diag = (config & 8) != 0;  // consumes no input bytes
  Vec6 last = Vec6::Zero();  // the last applied command
  for (int k = 0; k < kMaxSteps && !r.empty(); ++k) {
    adcs::Se3TrackingInput in;
    in.state = perturbed(sc.chaser[config & 3], raw, r);
    const adcs::Se3SpacecraftState& x = in.state;
    adcs::Se3DesiredState& d = in.desired;
    d = sc.desired;
    d.C_ND = sc.desired.C_ND * adcs::so3_exp(r.vec<3>());
    d.R_N += r.vec<3>();
    d.omega_DN_D += r.vec<3>();
    d.v_D += r.vec<3>();
    d.omega_dot_D += r.vec<3>();
    d.v_dot_D += r.vec<3>();
    const bool finite_in = fuzz::finite(x.C_NB) && fuzz::finite(x.R_N) && fuzz::finite(x.omega_BN_B) &&
                           fuzz::finite(x.v_B) && fuzz::finite(d.C_ND) && fuzz::finite(d.R_N) &&
                           fuzz::finite(d.omega_DN_D) && fuzz::finite(d.v_D) && fuzz::finite(d.omega_dot_D) &&
                           fuzz::finite(d.v_dot_D);
    adcs::Wrench w = adcs::Wrench::from_stacked(Vec6::Constant(fuzz::kNaN));  // must be overwritten
    typename Law::Diagnostics diag;
    Status s;
    if constexpr (std::is_same_v<Law, adcs::PrescribedTimeSe3>) {
      const double psi0 = law.psi_hat();
      const adcs::PrescribedTimeSe3Terms terms0 = law.terms();
      s = law.step(in, w, with_diag ? &diag : nullptr);
      fuzz::stat(which, "PrescribedTimeSe3", s);
      if (!fuzz::applied(s)) {
        FUZZ_CHECK(fuzz::same_bits(law.psi_hat(), psi0) && fuzz::same_bits(law.terms(), terms0),
                   "PrescribedTimeSe3: rejected step changed psi_hat or the terms");
      } else {
        FUZZ_CHECK(fuzz::finite(law.psi_hat()) && law.psi_hat() >= 0.0, "PrescribedTimeSe3: bad psi_hat");
        if (with_diag)
          FUZZ_CHECK(fuzz::same_bits(diag, law.terms()), "PrescribedTimeSe3: diagnostics differ from terms()");
      }
    } else {
      const Vec6 s0 = law.sliding_variable();
      s = law.step(in, w, with_diag ? &diag : nullptr);
      fuzz::stat(which, "FtsmcSe3", s);
      if (!fuzz::applied(s))
        FUZZ_CHECK(fuzz::same_bits_mat(law.sliding_variable(), s0), "FtsmcSe3: rejected step changed s");
      else if (with_diag)
        FUZZ_CHECK(fuzz::same_bits_mat(diag.s, law.sliding_variable()), "FtsmcSe3: diagnostics differ from s");
    }
    const Vec6 u = w.stacked();  // [M; F]
    FUZZ_CHECK(fuzz::finite(u), "SE(3) law: non-finite command");
    fuzz::check_status_vs_input(s, finite_in, "SE(3) law: non-finite input not rejected");
    if (!fuzz::applied(s)) {
      FUZZ_CHECK(fuzz::is_failure_command(adcs::FailurePolicy::safe_command, u, last) &&
                     fuzz::same_bits_mat(law.command(), last),
                 "SE(3) law: rejected step did not output the failure command or changed the last good one");
    } else {
      FUZZ_CHECK(s == Status::ok, "SE(3) law: undocumented usable status");
      last = u;
    }
    check_sat_quantize(u, sc.limit, q);  // the flight chain: u → sat → Q → clip
  }
}
}  // namespace ADCS_UNITY_ID

ADCS_FUZZ_ENTRY(fuzz_seed003) {
  using namespace ADCS_UNITY_ID;
  fuzz::Reader r(data, size);
  const int target = r.u8() % 3;
  const int config = r.u8();
  switch (target) {
    case 0: fuzz_law<adcs::PrescribedTimeSe3>(0, config, r); break;
    case 1: fuzz_law<adcs::FtsmcSe3>(1, config, r); break;
    default: fuzz_quantizer(config, r); break;
  }
  return 0;
}
