// libFuzzer harness, seed 004: the drag-free sample chain — DragFreeEskf (Algorithm 1 as the
// partitioned 18 + 9 filter in U-D form), three SaturatedEsf (Algorithm 2), fuse_axis (Algorithm 3) and
// DragFreeAdrc — driven by a fuzzed sequence of operations, plus a small generic Eskf<3, 1, 1, 1>
// and Pid<3> on their own. Input format: fuzz_common.hpp; first byte = target, second =
// configuration, then one operation byte per step.
//
// Asserted on every operation (besides "no crash, no sanitizer report"):
//  - a non-finite input gives exactly non_finite_input;
//  - a status that is not usable() leaves every estimate, covariance, θ and counter bitwise
//    unchanged (both filters for fuse_axis; integrals and the held command for ADRC and PID);
//  - an applied step leaves finite estimates and exactly symmetric covariances (DragFreeEskf: its
//    U-D factors with D >= 0 and U unit upper triangular, issue 20); SaturatedEsf
//    returns saturated exactly when the reading sits on a range bound (skip mode: estimate kept,
//    counter +1); fuse_axis leaves both filters holding the fused [r; ṙ; f̂];
//  - ADRC / PID commands are finite whatever the status, and ADRC's within ±limit when applied.
#include <array>
#include <cstdint>

#include "adcs/control/adrc.hpp"
#include "adcs/control/pid.hpp"
#include "adcs/estimate/eskf.hpp"
#include "adcs/estimate/fusion.hpp"
#include "fuzz_common.hpp"

// File-local, and named: the five harnesses are compiled in one unit (tests/fuzz/CMakeLists.txt).
namespace ADCS_UNITY_ID {
using adcs::Status;
using adcs::Vec3;
using Vec9 = adcs::Vec<9>;
using Vec27 = adcs::Vec<27>;
using Ix = adcs::DragFreeIndex;
constexpr int kMaxSteps = 12;

struct Models {
  adcs::DragFreeParams plant;
  adcs::DragFreeDiscrete d;
  adcs::DragFreeAxisModel axis[3];
  Models() {
    FUZZ_CHECK(adcs::drag_free_discretize(plant, d) == Status::ok, "set-up: discretisation");
    for (int j = 0; j < 3; ++j) FUZZ_CHECK(adcs::drag_free_axis_model(plant, j, axis[j]) == Status::ok, "set-up: axis");
  }
};
const Models& models() {
  static const Models m;
  return m;
}

adcs::DragFreeEskf::Params eskf_params(adcs::ThetaPolicy policy) {
  const Models& m = models();
  adcs::DragFreeEskf::Params e;
  e.A_d = m.d.A_d;
  e.B_d = m.d.B_d;
  e.B_e = m.d.B_e;
  e.C_d = m.d.C_d;
  e.q.head<6>().setConstant(8.5e-13);
  e.S = 1e-15 * adcs::Mat<9, 9>::Identity();
  e.R = 5e-16 * adcs::Mat<9, 9>::Identity();
  e.theta_policy = policy;
  e.period_s = m.plant.period_s;  // h of the discretisation
  return e;
}

adcs::SaturatedEsfParams esf_params(int axis, bool skip) {
  const Models& m = models();
  adcs::SaturatedEsfParams e;
  e.A_d = m.axis[axis].A_d;
  e.B_d = m.axis[axis].B_d;
  e.C = m.axis[axis].C;
  e.D = m.axis[axis].D;
  e.q = 8.5e-13;
  e.S = 1e-16;
  e.R_a = 5e-24;
  e.y_min = m.plant.accel_min;
  e.y_max = m.plant.accel_max;
  e.saturation = skip ? adcs::SaturationUpdate::skip : adcs::SaturationUpdate::truncated;
  e.period_s = m.plant.period_s;
  return e;
}

// ---- snapshots ("untouched" = bitwise equal) ----------------------------------------------
struct Alg1Snap {
  Vec27 x;
  adcs::Mat<27, 27> P;
  double theta;
  long proj;
  explicit Alg1Snap(const adcs::DragFreeEskf& f)
      : x(f.state()), P(f.covariance()), theta(f.theta()), proj(f.psd_projections()) {}
  bool operator==(const Alg1Snap& o) const {
    return fuzz::same_bits_mat(x, o.x) && fuzz::same_bits_mat(P, o.P) && fuzz::same_bits(theta, o.theta) &&
           proj == o.proj;
  }
};
struct Alg2Snap {
  Vec3 x;
  adcs::Mat3 P;
  long sat;
  explicit Alg2Snap(const adcs::SaturatedEsf& f) : x(f.state()), P(f.covariance()), sat(f.saturated_updates()) {}
  bool operator==(const Alg2Snap& o) const {
    return fuzz::same_bits_mat(x, o.x) && fuzz::same_bits_mat(P, o.P) && sat == o.sat;
  }
};

template <class Derived>
bool healthy(const Eigen::MatrixBase<Derived>& P) {
  return fuzz::finite(P.eval()) && P == P.transpose();
}

template <int N>
bool ud_healthy(const adcs::UdFactors<N>& f) {
  return fuzz::finite(f.U) && fuzz::finite(f.D) && (f.D.array() >= 0.0).all() && f.U.isUpperTriangular(0.0) &&
         f.U.diagonal().isOnes(0.0);
}

void check_alg1(const adcs::DragFreeEskf& f, Status s, const Alg1Snap& before, bool finite_in, const char* what) {
  fuzz::check_status_vs_input(s, finite_in, what);
  const Alg1Snap after(f);
  if (!fuzz::applied(s)) {
    FUZZ_CHECK(after == before, what);
    return;
  }
  FUZZ_CHECK(s == Status::ok, "DragFreeEskf: undocumented usable status");
  FUZZ_CHECK(fuzz::finite(after.x) && healthy(after.P), "DragFreeEskf: committed a non-finite or asymmetric estimate");
  // U-D factors (issue 20): PSD by construction, D >= 0 and U unit upper triangular after every
  // committed step, whatever the inputs.
  FUZZ_CHECK(ud_healthy(f.block1().factors()) && ud_healthy(f.block2().factors()),
             "DragFreeEskf: U-D factors left the PSD cone (D < 0) or lost their shape");
}

void check_alg2(const adcs::SaturatedEsf& f, Status s, const Alg2Snap& before, bool finite_in, const char* what) {
  fuzz::check_status_vs_input(s, finite_in, what);
  const Alg2Snap after(f);
  if (!fuzz::applied(s)) {
    FUZZ_CHECK(after == before, what);
    return;
  }
  // A skipped saturated update keeps P as it was (possibly an asymmetric set_estimate value).
  FUZZ_CHECK(fuzz::finite(after.x) && fuzz::finite(after.P) &&
                 (fuzz::same_bits_mat(after.P, before.P) || healthy(after.P)),
             "SaturatedEsf: committed a non-finite or asymmetric estimate");
}

// ---- target 0: the chain ------------------------------------------------------------------
void fuzz_chain(int config, fuzz::Reader& r) {
  static const adcs::DragFreeEskf alg1_protos[2] = {adcs::DragFreeEskf(eskf_params(adcs::ThetaPolicy::trace_optimal)),
                                                    adcs::DragFreeEskf(eskf_params(adcs::ThetaPolicy::fixed_initial))};
  static const adcs::SaturatedEsf alg2_protos[2][3] = {
      {adcs::SaturatedEsf(esf_params(0, false)), adcs::SaturatedEsf(esf_params(1, false)),
       adcs::SaturatedEsf(esf_params(2, false))},
      {adcs::SaturatedEsf(esf_params(0, true)), adcs::SaturatedEsf(esf_params(1, true)),
       adcs::SaturatedEsf(esf_params(2, true))}};
  adcs::DragFreeEskf alg1 = alg1_protos[config & 1];
  const bool skip = (config & 2) != 0;
  adcs::SaturatedEsf alg2[3] = {alg2_protos[skip][0], alg2_protos[skip][1], alg2_protos[skip][2]};
  adcs::DragFreeAdrcParams ap;
  ap.x_law = static_cast<adcs::DragFreeXLaw>((config >> 2) % 3);
  ap.integral = (config & 32) ? adcs::IntegralForm::raw_sum : adcs::IntegralForm::scaled_sum;
  ap.pid_ki = (config & 64) ? 0.5 : 0.0;
  ap.on_failure = (config & 128) ? adcs::FailurePolicy::hold_last : adcs::FailurePolicy::safe_command;
  adcs::DragFreeAdrc adrc(ap);
  FUZZ_CHECK(adrc.status() == Status::ok, "set-up: ADRC");
  const adcs::FusedCovariance mode =
      (config & 128) ? adcs::FusedCovariance::literal : adcs::FusedCovariance::block_diagonal;
  Vec9 u = Vec9::Zero();  // the last applied ADRC command
  for (int k = 0; k < kMaxSteps && !r.empty(); ++k) {
    const int op = r.u8();
    const int j = (op >> 4) % 3;
    switch (op % 7) {
      case 0: {  // Algorithm 1 time update
        const Vec9 uu = u + r.vec<9>(), df = r.vec<9>();
        const Alg1Snap before(alg1);
        const Status s = alg1.predict(uu, df);
        fuzz::stat(0, "DragFreeEskf::predict", s);
        check_alg1(alg1, s, before, fuzz::finite(uu) && fuzz::finite(df), "DragFreeEskf::predict");
        break;
      }
      case 1: {  // Algorithm 1 measurement update
        const Vec9 Y = Vec9::Constant(1e-8) + r.vec<9>();
        const Alg1Snap before(alg1);
        const Status s = alg1.update(Y);
        fuzz::stat(1, "DragFreeEskf::update", s);
        check_alg1(alg1, s, before, fuzz::finite(Y), "DragFreeEskf::update");
        break;
      }
      case 2: {  // Algorithm 2 time update
        const double uu = u(3 + j) + r.value(), df = r.value();
        const Alg2Snap before(alg2[j]);
        const Status s = alg2[j].predict(uu, df);
        fuzz::stat(2, "SaturatedEsf::predict", s);
        check_alg2(alg2[j], s, before, fuzz::finite(uu) && fuzz::finite(df), "SaturatedEsf::predict");
        if (fuzz::applied(s)) FUZZ_CHECK(s == Status::ok, "SaturatedEsf::predict: undocumented usable status");
        break;
      }
      case 3: {  // Algorithm 2 measurement update (readings around the ±6e-6 range)
        const double y = 1e-7 + r.value(), uu = u(3 + j) + r.value();
        const Alg2Snap before(alg2[j]);
        const Status s = alg2[j].update(y, uu);
        fuzz::stat(3, "SaturatedEsf::update", s);
        check_alg2(alg2[j], s, before, fuzz::finite(y) && fuzz::finite(uu), "SaturatedEsf::update");
        if (fuzz::applied(s)) {
          FUZZ_CHECK(s == Status::ok || s == Status::saturated, "SaturatedEsf::update: undocumented usable status");
          const bool on_bound = y >= models().plant.accel_max || y <= models().plant.accel_min;
          FUZZ_CHECK((s == Status::saturated) == on_bound, "SaturatedEsf::update: saturated flag wrong");
          const Alg2Snap after(alg2[j]);
          FUZZ_CHECK(after.sat == before.sat + (on_bound ? 1 : 0), "SaturatedEsf: saturated-update count wrong");
          if (on_bound && skip)
            FUZZ_CHECK(fuzz::same_bits_mat(after.x, before.x) && fuzz::same_bits_mat(after.P, before.P),
                       "SaturatedEsf: skip mode changed the estimate");
        }
        break;
      }
      case 4: {  // Algorithm 3 (axis may be invalid)
        const int axis = static_cast<int>(r.u8() % 5) - 1;
        const int jj = axis >= 0 && axis < 3 ? axis : j;
        const Alg1Snap b1(alg1);
        const Alg2Snap b2(alg2[jj]);
        const Status s = adcs::fuse_axis(alg1, alg2[jj], axis, mode);
        fuzz::stat(4, "fuse_axis", s);
        if (axis < 0 || axis > 2) FUZZ_CHECK(s == Status::invalid_parameter, "fuse_axis: bad axis accepted");
        if (!fuzz::applied(s)) {
          FUZZ_CHECK(Alg1Snap(alg1) == b1 && Alg2Snap(alg2[jj]) == b2, "fuse_axis: rejected but changed a filter");
          break;
        }
        FUZZ_CHECK(s == Status::ok, "fuse_axis: undocumented usable status");
        const Vec27& x1 = alg1.state();
        const Vec3& x2 = alg2[jj].state();
        FUZZ_CHECK(x2(0) == x1(Ix::r + axis) && x2(1) == x1(Ix::r_dot + axis) && x2(2) == x1(Ix::F_Dsc + axis) &&
                       x2(2) == b2.x(2) && x2(0) == b1.x(Ix::r + axis),
                   "fuse_axis: filters do not hold the fused estimate");
        FUZZ_CHECK(healthy(alg1.covariance()) && fuzz::finite(alg2[jj].covariance()), "fuse_axis: bad covariance");
        break;
      }
      case 5: {  // ADRC on the fused posterior (with fuzzed offsets) and Algorithm 2's f̂
        const Vec27 x_hat = alg1.state() + r.vec<27>();
        const Vec3 F(alg2[0].state()(2), alg2[1].state()(2), alg2[2].state()(2));
        const Vec3 F_D = F + r.vec<3>(), phi_cmd = r.vec<3>();
        const Vec3 ia = adrc.attitude_integral(), id = adrc.drag_free_integral();
        adcs::DragFreeActuation act = adcs::DragFreeActuation::from_stacked(Vec9::Constant(fuzz::kNaN));
        const Status s = adrc.step(adcs::DragFreeAdrcInput{x_hat, F_D, phi_cmd}, act);
        const Vec9 out = act.stacked();  // [T_Csc; F_Csc; T_Ctm]
        fuzz::stat(5, "DragFreeAdrc", s);
        FUZZ_CHECK(fuzz::finite(out), "DragFreeAdrc: non-finite command");
        fuzz::check_status_vs_input(s, fuzz::finite(x_hat) && fuzz::finite(F_D) && fuzz::finite(phi_cmd),
                                    "DragFreeAdrc: non-finite input not rejected");
        if (!fuzz::applied(s)) {
          FUZZ_CHECK(fuzz::is_failure_command(ap.on_failure, out, u) && fuzz::same_bits_mat(adrc.attitude_integral(), ia) &&
                         fuzz::same_bits_mat(adrc.drag_free_integral(), id),
                     "DragFreeAdrc: rejected step changed the command or an integral");
          break;
        }
        FUZZ_CHECK(out.cwiseAbs().maxCoeff() <= ap.limit, "DragFreeAdrc: command beyond the actuator cube");
        FUZZ_CHECK(fuzz::finite(adrc.attitude_integral()) && fuzz::finite(adrc.drag_free_integral()),
                   "DragFreeAdrc: non-finite integral committed");
        u = out;
        break;
      }
      default: {  // warm starts (fusion interface): any values, non-finite ones refused untouched
        if (op & 8) {
          const Vec3 x = r.vec<3>();
          adcs::Mat3 P;
          for (int c = 0; c < 3; ++c) P.col(c) = r.vec<3>();
          const Vec3 xs = alg2[j].state() + x;
          const bool fin = fuzz::finite(xs) && fuzz::finite(P);
          const Alg2Snap before(alg2[j]);
          const Status s = alg2[j].set_estimate(xs, P);
          FUZZ_CHECK((s == Status::ok) == fin, "SaturatedEsf::set_estimate: wrong status");
          if (s != Status::ok) FUZZ_CHECK(Alg2Snap(alg2[j]) == before, "SaturatedEsf::set_estimate: rejected but changed");
        } else {
          const Vec27 x = alg1.state() + r.vec<27>();
          const double scale = r.value();
          const adcs::Mat<27, 27> P = alg1.covariance() * scale;
          const Alg1Snap before(alg1);
          const Status s = alg1.set_estimate(x, P);
          if (!fuzz::finite(x) || !fuzz::finite(P))
            FUZZ_CHECK(s == Status::non_finite_input, "DragFreeEskf::set_estimate: non-finite accepted");
          if (s != Status::ok) FUZZ_CHECK(Alg1Snap(alg1) == before, "DragFreeEskf::set_estimate: rejected but changed");
        }
        break;
      }
    }
  }
}

// ---- target 1: a generic Eskf<3, 1, 1, 1> (Algorithm 1 on the accelerometer axis model) ---
using Small = adcs::Eskf<3, 1, 1, 1>;
void fuzz_small_eskf(int config, fuzz::Reader& r) {
  static const Small protos[2] = {
      Small([] {
        Small::Params p;
        const adcs::DragFreeAxisModel& m = models().axis[0];
        p.A_d = m.A_d;
        p.B_d = m.B_d;
        p.B_e = m.B_e;
        p.C_d = m.C;
        p.q(0) = 8.5e-13;
        p.S(0, 0) = 1e-16;
        p.R(0, 0) = 1e-12;
        p.period_s = models().plant.period_s;  // the axis model's h
        return p;
      }()),
      Small([] {
        Small::Params p;
        p.A_d << 1, 0.1, 0, 0, 1, 0.1, 0, 0, 1;
        p.B_d << 0, 0.1, 0;
        p.B_e << 0, 0, 1;
        p.C_d << 1, 0, 0;
        p.q(0) = 1e-4;
        p.R(0, 0) = 1e-2;
        p.theta_policy = adcs::ThetaPolicy::fixed_initial;
        p.period_s = 0.1;  // the h in A_d, B_d above
        return p;
      }())};
  Small f = protos[config & 1];
  for (int k = 0; k < kMaxSteps && !r.empty(); ++k) {
    const int op = r.u8();
    const Vec3 x0 = f.state();
    const adcs::Mat3 P0 = f.covariance();
    const double th0 = f.theta();
    const long pr0 = f.psd_projections();
    Status s;
    bool fin = true;
    switch (op % 4) {
      case 0: {
        const adcs::Vec<1> u = r.vec<1>(), df = r.vec<1>();
        fin = fuzz::finite(u) && fuzz::finite(df);
        s = f.predict(u, df);
        break;
      }
      case 1: {
        const adcs::Vec<1> y = r.vec<1>();
        fin = fuzz::finite(y);
        s = f.update(y);
        break;
      }
      case 2: {
        const Vec3 x = r.vec<3>();
        adcs::Mat3 P;
        for (int c = 0; c < 3; ++c) P.col(c) = r.vec<3>();
        P = (0.5 * (P + P.transpose())).eval();  // symmetric, not necessarily PSD
        fin = fuzz::finite(x) && fuzz::finite(P);
        s = f.set_estimate(x, P);
        break;
      }
      default: {
        const std::array<int, 2> idx{static_cast<int>(r.u8() % 5) - 1, static_cast<int>(r.u8() % 5) - 1};
        const adcs::Vec<2> xo = r.vec<2>();
        adcs::Mat<2, 2> Po;
        Po.col(0) = r.vec<2>();
        Po.col(1) = r.vec<2>();
        const bool idx_ok = idx[0] >= 0 && idx[0] < 3 && idx[1] >= 0 && idx[1] < 3 && idx[0] != idx[1];
        s = f.replace_substate<2>(idx, xo, Po);
        if (!idx_ok) FUZZ_CHECK(s == Status::invalid_parameter, "Eskf::replace_substate: bad indices accepted");
        fin = !idx_ok || (fuzz::finite(xo) && fuzz::finite(Po));
        break;
      }
    }
    fuzz::stat(6, "Eskf<3,1,1,1>", s);
    fuzz::check_status_vs_input(s, fin, "Eskf: non-finite input not rejected");
    if (!fuzz::applied(s)) {
      FUZZ_CHECK(fuzz::same_bits_mat(f.state(), x0) && fuzz::same_bits_mat(f.covariance(), P0) &&
                     fuzz::same_bits(f.theta(), th0) && f.psd_projections() == pr0,
                 "Eskf: rejected step changed the estimate");
    } else {
      FUZZ_CHECK(s == Status::ok, "Eskf: undocumented usable status");
      FUZZ_CHECK(fuzz::finite(f.state()) && fuzz::finite(f.covariance()), "Eskf: non-finite estimate committed");
      if (op % 4 < 2) FUZZ_CHECK(healthy(f.covariance()), "Eskf: asymmetric covariance");
    }
  }
}

// ---- target 2: Pid<3> on its own ----------------------------------------------------------
void fuzz_pid(int config, fuzz::Reader& r) {
  adcs::PidParams<3> p;
  p.kp = Vec3(5.55, 1.0, 0.0);
  p.ki = (config & 1) ? Vec3(0.5, 0.0, 2.0) : Vec3::Zero();
  p.kd = Vec3(9.0, 0.0, 1.0);
  p.period_s = (config & 2) ? 1.0 : 0.1;
  p.on_failure = (config & 4) ? adcs::FailurePolicy::hold_last : adcs::FailurePolicy::safe_command;
  adcs::Pid<3> pid(p);
  Vec3 last = Vec3::Constant(-7.0);
  Vec3 last_good = Vec3::Zero();  // the Pid's own last good output (zero after construction)
  for (int k = 0; k < kMaxSteps && !r.empty(); ++k) {
    const Vec3 e_p = r.vec<3>(), e_d = r.vec<3>();
    const Vec3 i0 = pid.integral();
    adcs::PidOutput<3> po;
    po.u = last;
    const Status s = pid.step(adcs::PidInput<3>{e_p, e_d}, po);
    const Vec3& out = po.u;
    const Vec3 held = last_good;
    fuzz::stat(7, "Pid<3>", s);
    fuzz::check_status_vs_input(s, fuzz::finite(e_p) && fuzz::finite(e_d), "Pid: non-finite input not rejected");
    FUZZ_CHECK(fuzz::finite(out) || !fuzz::finite(last), "Pid: non-finite output");
    if (!fuzz::applied(s)) {
      FUZZ_CHECK((fuzz::is_failure_command(p.on_failure, out, held) || !fuzz::finite(held)) &&
                     fuzz::same_bits_mat(pid.integral(), i0),
                 "Pid: rejected step changed the output or the integral");
      continue;
    }
    FUZZ_CHECK(s == Status::ok && fuzz::finite(out) && fuzz::finite(pid.integral()), "Pid: non-finite result");
    last = out;
    last_good = out;
  }
}
}  // namespace ADCS_UNITY_ID

ADCS_FUZZ_ENTRY(fuzz_seed004) {
  using namespace ADCS_UNITY_ID;
  fuzz::Reader r(data, size);
  const int target = r.u8() % 3;
  const int config = r.u8();
  switch (target) {
    case 0: fuzz_chain(config, r); break;
    case 1: fuzz_small_eskf(config, r); break;
    default: fuzz_pid(config, r); break;
  }
  return 0;
}
