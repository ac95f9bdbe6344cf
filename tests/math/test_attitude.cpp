// Property tests of the attitude parameterisations (manif / Basilisk style): so3 helpers,
// scalar-first quaternions, MRPs (seed 001 eq. (6), spec §A.2.5) and Euler angles (x-y-z of
// seed 002 eq. (3), spec §B.2, and 3-2-1). Every analytic derivative is checked against central
// finite differences; truth values come from independent formulas written out in this file
// (Rodrigues, Schaub & Junkins elementwise DCMs, Eigen's Hamilton quaternion).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>

#include "adcs/math/euler.hpp"
#include "adcs/math/mrp.hpp"
#include "adcs/math/quaternion.hpp"
#include "adcs/math/so3.hpp"

namespace ADCS_UNITY_ID {

using adcs::Mat3;
using adcs::QuaternionSF;
using adcs::Status;
using adcs::Vec3;
using adcs::Vec4;

constexpr int kSamples = 100;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Fixed-seed generator so every run sees the same samples.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen_); }
  double normal() { return std::normal_distribution<double>(0.0, 1.0)(gen_); }
  Vec3 vec3(double lo = -1.0, double hi = 1.0) { return Vec3(uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)); }
  Vec3 unit3() {
    Vec3 v(normal(), normal(), normal());
    while (v.norm() < 1e-3) v = Vec3(normal(), normal(), normal());
    return v.normalized();
  }
  //! Uniform on S^3 (both signs of w).
  QuaternionSF quat() {
    Vec4 q(normal(), normal(), normal(), normal());
    while (q.norm() < 1e-3) q = Vec4(normal(), normal(), normal(), normal());
    return QuaternionSF::from_scalar_first(q.normalized());
  }
  //! MRP with uniformly random direction and norm in [lo, hi].
  Vec3 mrp(double lo, double hi) { return unit3() * uniform(lo, hi); }
  //! x-y-z or 3-2-1 angles with the middle (pitch) angle in (-max_pitch, max_pitch).
  Vec3 euler(double max_pitch = 89.0 * kDeg) {
    return Vec3(uniform(-kPi, kPi), uniform(-max_pitch, max_pitch), uniform(-kPi, kPi));
  }

 private:
  std::mt19937_64 gen_;
};

double max_abs(const Eigen::Ref<const Eigen::MatrixXd>& m) { return m.cwiseAbs().maxCoeff(); }

::testing::AssertionResult is_rotation(const Mat3& C, double tol = 1e-14) {
  const double orth = max_abs(C.transpose() * C - Mat3::Identity());
  const double det = C.determinant();
  if (orth <= tol && std::abs(det - 1.0) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "|C^T C - I| = " << orth << ", det = " << det << "\n" << C;
}

//! Distance between two quaternions up to the q ~ -q ambiguity.
double quat_dist(const QuaternionSF& a, const QuaternionSF& b) {
  return std::min((a.scalar_first() - b.scalar_first()).norm(), (a.scalar_first() + b.scalar_first()).norm());
}

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

//! Central difference d/dt f(t) at t = 0.
template <class F>
auto central_diff(F f, double h = 1e-5) {
  using R = decltype(f(0.0));
  return R((f(h) - f(-h)) / (2.0 * h));
}

//! Relative error |num - ana| / |ana| (Frobenius).
template <class A, class B>
double rel_err(const A& num, const B& ana) {
  return (num - ana).norm() / std::max(ana.norm(), 1e-300);
}

// Independent truth: the passive (frame) rotation by phi about unit axis a, Rodrigues' formula
// applied to a vector without any matrix: C x = x cos(phi) - (a x x) sin(phi) + a (a.x)(1 - cos(phi)).
Vec3 rodrigues_frame_rotate(const Vec3& a, double phi, const Vec3& x) {
  return x * std::cos(phi) - a.cross(x) * std::sin(phi) + a * a.dot(x) * (1.0 - std::cos(phi));
}

// Spec §B.2 elementary frame rotations, typed in from the spec (not from so3.hpp).
Mat3 spec_R1(double a) {
  Mat3 m;
  m << 1, 0, 0, 0, std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a);
  return m;
}
Mat3 spec_R2(double a) {
  Mat3 m;
  m << std::cos(a), 0, -std::sin(a), 0, 1, 0, std::sin(a), 0, std::cos(a);
  return m;
}
Mat3 spec_R3(double a) {
  Mat3 m;
  m << std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a), 0, 0, 0, 1;
  return m;
}

// =============================================================================================
// so3

TEST(So3, SkewIsTheCrossProductAndVeeItsInverse) {
  Rng rng(0x5031);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 v = rng.vec3(-3, 3), w = rng.vec3(-3, 3);
    const Mat3 S = adcs::skew(v);
    EXPECT_LE((S * w - v.cross(w)).norm(), 1e-15 * (1.0 + v.norm() * w.norm()));
    EXPECT_EQ(S.transpose(), -S);
    EXPECT_LE((S * v).norm(), 1e-15 * v.squaredNorm());
    EXPECT_EQ(adcs::vee(S), v);  // (v - (-v)) / 2 is exact
    // vee of a general matrix is the vee of its skew-symmetric part.
    const Mat3 M = Mat3::Random();
    EXPECT_LE((adcs::vee(M) - adcs::vee(0.5 * (M - M.transpose()))).norm(), 1e-15);
    EXPECT_EQ(adcs::skew(adcs::vee(S)), S);
    // [v]x [w]x - [w]x [v]x = [v x w]x  (Lie bracket of so(3)).
    EXPECT_LE(max_abs(S * adcs::skew(w) - adcs::skew(w) * S - adcs::skew(v.cross(w))), 1e-13);
  }
}

TEST(So3, ExpIsRodriguesAndMatchesEigenAngleAxis) {
  for (const Vec3& phi : {Vec3(0.3, -1.2, 2.0), Vec3(1e-9, 2e-9, -1e-9), Vec3(0.0, 0.0, 0.0),
                         Vec3(3e-5, -1e-5, 2e-5)}) {
    const Mat3 R = adcs::so3_exp(phi);
    const double a = phi.norm();
    const Mat3 ref = a > 0 ? Eigen::AngleAxisd(a, phi / a).toRotationMatrix() : Mat3::Identity();
    EXPECT_LT((R - ref).norm(), 1e-15) << phi.transpose();
    EXPECT_LT((R * R.transpose() - Mat3::Identity()).norm(), 1e-15);
    EXPECT_LT((R * phi - phi).norm(), 1e-15);  // the axis is fixed
  }
}

TEST(So3, FrameRotationsAreProperRotationsMatchingTheSpec) {
  Rng rng(0x5032);
  for (int k = 0; k < kSamples; ++k) {
    const double a = rng.uniform(-2 * kPi, 2 * kPi), b = rng.uniform(-2 * kPi, 2 * kPi);
    const Mat3 R[3] = {adcs::frame_rotation_1(a), adcs::frame_rotation_2(a), adcs::frame_rotation_3(a)};
    const Mat3 Rb[3] = {adcs::frame_rotation_1(b), adcs::frame_rotation_2(b), adcs::frame_rotation_3(b)};
    const Mat3 Rab[3] = {adcs::frame_rotation_1(a + b), adcs::frame_rotation_2(a + b),
                         adcs::frame_rotation_3(a + b)};
    const Mat3 Rneg[3] = {adcs::frame_rotation_1(-a), adcs::frame_rotation_2(-a), adcs::frame_rotation_3(-a)};
    const Mat3 spec[3] = {spec_R1(a), spec_R2(a), spec_R3(a)};
    for (int i = 0; i < 3; ++i) {
      SCOPED_TRACE(i + 1);
      EXPECT_TRUE(is_rotation(R[i]));
      EXPECT_LE(max_abs(R[i] - spec[i]), 0.0);
      EXPECT_LE(max_abs(R[i] * Rb[i] - Rab[i]), 1e-14);  // one-parameter subgroup
      EXPECT_LE(max_abs(Rneg[i] - R[i].transpose()), 0.0);
      const Vec3 e = Vec3::Unit(i);
      EXPECT_LE((R[i] * e - e).norm(), 0.0);  // the axis is fixed
      // Frame rotation = passive rotation by +a about e_i (same sense as the quaternion).
      const Vec3 x = rng.vec3();
      EXPECT_LE((R[i] * x - rodrigues_frame_rotate(e, a, x)).norm(), 1e-14);
      EXPECT_LE(max_abs(R[i] - adcs::quat_to_dcm(QuaternionSF::from_axis_angle(e, a))), 1e-14);
    }
  }
}

// =============================================================================================
// Quaternion

TEST(Quaternion, NamedFactoriesKeepTheirArgumentOrder) {
  const QuaternionSF a = QuaternionSF::from_scalar_first(0.1, 0.2, 0.3, 0.4);
  EXPECT_EQ(a.w(), 0.1);
  EXPECT_EQ(a.vec(), Vec3(0.2, 0.3, 0.4));
  EXPECT_EQ(a.scalar_first(), Vec4(0.1, 0.2, 0.3, 0.4));

  const QuaternionSF b = QuaternionSF::from_scalar_last(0.2, 0.3, 0.4, 0.1);
  EXPECT_EQ(b.w(), 0.1);
  EXPECT_EQ(b.vec(), Vec3(0.2, 0.3, 0.4));
  EXPECT_EQ(b.scalar_first(), a.scalar_first());

  const QuaternionSF c = QuaternionSF::from_scalar_first(Vec4(0.1, 0.2, 0.3, 0.4));
  EXPECT_EQ(c.scalar_first(), a.scalar_first());

  // The trap the named factories avoid: Eigen's constructor takes (w,x,y,z) but stores x,y,z,w.
  const Eigen::Quaterniond eig(0.1, 0.2, 0.3, 0.4);
  EXPECT_EQ(eig.coeffs(), Vec4(0.2, 0.3, 0.4, 0.1));
  EXPECT_EQ(eig.w(), a.w());

  const QuaternionSF id = QuaternionSF::identity();
  EXPECT_EQ(id.scalar_first(), Vec4(1, 0, 0, 0));
  EXPECT_EQ(adcs::quat_to_dcm(id), Mat3::Identity());
}

TEST(Quaternion, NormConjugateAndCanonical) {
  Rng rng(0x5101);
  for (int k = 0; k < kSamples; ++k) {
    const QuaternionSF q = rng.quat();
    const QuaternionSF s = QuaternionSF::from_scalar_first(3.7 * q.scalar_first());
    EXPECT_NEAR(s.norm(), 3.7, 1e-14);
    EXPECT_NEAR(s.normalized().norm(), 1.0, 1e-15);
    EXPECT_LE((s.normalized().scalar_first() - q.scalar_first()).norm(), 1e-15);

    const QuaternionSF qc = q.conjugate();
    EXPECT_EQ(qc.w(), q.w());
    EXPECT_EQ(qc.vec(), -q.vec());
    EXPECT_LE(max_abs(adcs::quat_to_dcm(qc) - adcs::quat_to_dcm(q).transpose()), 1e-15);
    EXPECT_LE(quat_dist(adcs::compose(q, qc), QuaternionSF::identity()), 1e-15);

    const QuaternionSF c = q.canonical();
    EXPECT_GE(c.w(), 0.0);
    EXPECT_TRUE(c.scalar_first() == q.scalar_first() || c.scalar_first() == -q.scalar_first());
    // -q is the same attitude.
    const QuaternionSF neg = QuaternionSF::from_scalar_first(-q.scalar_first());
    EXPECT_EQ(adcs::quat_to_dcm(neg), adcs::quat_to_dcm(q));
    EXPECT_EQ(neg.canonical().scalar_first(), c.scalar_first());
  }
}

TEST(Quaternion, DcmIsProperRotationAndMatchesEigenHamilton) {
  Rng rng(0x5102);
  for (int k = 0; k < kSamples; ++k) {
    const QuaternionSF q = rng.quat();
    const Mat3 C = adcs::quat_to_dcm(q);
    EXPECT_TRUE(is_rotation(C));
    // Second implementation: Eigen's (Hamilton, active) rotation matrix is C^T.
    const Eigen::Quaterniond e(q.w(), q.vec()(0), q.vec()(1), q.vec()(2));
    EXPECT_LE(max_abs(C - e.toRotationMatrix().transpose()), 1e-15);
    // The vector part is the rotation axis: C v = v.
    EXPECT_LE((C * q.vec() - q.vec()).norm(), 1e-15);
  }
}

TEST(Quaternion, ComposeIsTheDcmProduct) {
  Rng rng(0x5103);
  for (int k = 0; k < kSamples; ++k) {
    const QuaternionSF a = rng.quat(), b = rng.quat(), c = rng.quat();
    const QuaternionSF ab = adcs::compose(a, b);
    EXPECT_LE(max_abs(adcs::quat_to_dcm(ab) - adcs::quat_to_dcm(a) * adcs::quat_to_dcm(b)), 1e-14);
    EXPECT_NEAR(ab.norm(), 1.0, 1e-15);
    // Schaub's composition is the reversed Hamilton product.
    const Eigen::Quaterniond ea(a.w(), a.vec()(0), a.vec()(1), a.vec()(2));
    const Eigen::Quaterniond eb(b.w(), b.vec()(0), b.vec()(1), b.vec()(2));
    const Eigen::Quaterniond eba = eb * ea;
    EXPECT_LE((ab.scalar_first() - Vec4(eba.w(), eba.x(), eba.y(), eba.z())).norm(), 1e-15);
    // Associative, identity is neutral.
    EXPECT_LE((adcs::compose(ab, c).scalar_first() - adcs::compose(a, adcs::compose(b, c)).scalar_first()).norm(),
              1e-15);
    EXPECT_EQ(adcs::compose(QuaternionSF::identity(), a).scalar_first(), a.scalar_first());
    EXPECT_EQ(adcs::compose(a, QuaternionSF::identity()).scalar_first(), a.scalar_first());
  }
}

TEST(Quaternion, DcmToQuatRoundTripsEverywhere) {
  Rng rng(0x5104);
  auto check = [](const QuaternionSF& q, double tol) {
    const QuaternionSF r = adcs::dcm_to_quat(adcs::quat_to_dcm(q));
    EXPECT_GE(r.w(), 0.0);
    EXPECT_NEAR(r.norm(), 1.0, 1e-15);
    EXPECT_LE(quat_dist(r, q), tol) << "q = " << q.scalar_first().transpose()
                                    << "\nr = " << r.scalar_first().transpose();
    // When w is clearly nonzero the sign is fixed: r is the canonical representative.
    if (std::abs(q.w()) > 1e-6) {
      EXPECT_LE((r.scalar_first() - q.canonical().scalar_first()).norm(), tol);
    }
  };
  for (int k = 0; k < kSamples; ++k) check(rng.quat(), 1e-15 * 4);
  // Near-180 deg rotations (w ~ 0, both signs, and exactly 0), random axes.
  for (int k = 0; k < kSamples; ++k) {
    const double w = (k % 5 == 0) ? 0.0 : rng.uniform(-1e-6, 1e-6);
    const Vec3 v = rng.unit3() * std::sqrt(1.0 - w * w);
    check(QuaternionSF::from_scalar_first(w, v(0), v(1), v(2)), 4e-15);
  }
  // Each branch of Shepperd's method: 180 deg (and nearly) about each axis, w largest.
  for (int i = 0; i < 3; ++i) {
    for (double angle : {kPi, kPi - 1e-9, -kPi + 1e-9, 0.5, 2.0}) {
      check(QuaternionSF::from_axis_angle(Vec3::Unit(i), angle), 4e-15);
      check(QuaternionSF::from_axis_angle((Vec3(1, 1, 1) + 1e-3 * Vec3::Unit(i)).normalized(), angle), 4e-15);
    }
  }
  // Identity is reproduced exactly.
  EXPECT_EQ(adcs::dcm_to_quat(Mat3::Identity()).scalar_first(), Vec4(1, 0, 0, 0));
  // A DCM built without quaternions (Euler) round trips through the DCM.
  for (int k = 0; k < kSamples; ++k) {
    const Mat3 C = adcs::euler321_to_dcm(rng.euler(kPi / 2));
    EXPECT_LE(max_abs(adcs::quat_to_dcm(adcs::dcm_to_quat(C)) - C), 1e-14);
  }
}

TEST(Quaternion, FromAxisAngleMatchesRodrigues) {
  Rng rng(0x5105);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 a = rng.unit3();
    const double phi = rng.uniform(-2 * kPi, 2 * kPi);
    const QuaternionSF q = QuaternionSF::from_axis_angle(a, phi);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    const Mat3 C = adcs::quat_to_dcm(q);
    for (int j = 0; j < 3; ++j) {
      const Vec3 x = rng.vec3(-2, 2);
      EXPECT_LE((C * x - rodrigues_frame_rotate(a, phi, x)).norm(), 1e-14);
    }
    // Principal angle from the trace: tr C = 1 + 2 cos(phi).
    EXPECT_NEAR(C.trace(), 1.0 + 2.0 * std::cos(phi), 1e-14);
  }
}

// =============================================================================================
// MRP, seed 001 eq. (6), spec §A.2.5

TEST(Mrp, DcmIsProperRotationAndMatchesQuaternionPath) {
  Rng rng(0x6001);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 s = rng.mrp(0.0, 3.0);
    const Mat3 C = adcs::mrp_to_dcm(s);
    EXPECT_TRUE(is_rotation(C, 1e-14)) << "sigma = " << s.transpose();
    EXPECT_LE(max_abs(C - adcs::quat_to_dcm(adcs::mrp_to_quat(s))), 1e-14);
    EXPECT_NEAR(adcs::mrp_to_quat(s).norm(), 1.0, 1e-15);
    // sigma is along the rotation axis.
    EXPECT_LE((C * s - s).norm(), 1e-14 * (1.0 + s.norm()));
  }
  // |sigma| = 1 is a 180 deg rotation: C = 2 s s^T - I.
  const Vec3 s1 = Vec3(1, -2, 2) / 3.0;
  EXPECT_LE(max_abs(adcs::mrp_to_dcm(s1) - (2.0 * s1 * s1.transpose() - Mat3::Identity())), 1e-15);
  EXPECT_EQ(adcs::mrp_to_dcm(Vec3::Zero()), Mat3::Identity());
}

TEST(Mrp, DcmRoundTripGivesShortSet) {
  Rng rng(0x6002);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 s = rng.mrp(0.0, 0.999);
    const Vec3 r = adcs::dcm_to_mrp(adcs::mrp_to_dcm(s));
    EXPECT_LE((r - s).norm(), 1e-14) << s.transpose();
  }
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 s = rng.mrp(1.001, 3.0);
    const Vec3 r = adcs::dcm_to_mrp(adcs::mrp_to_dcm(s));
    Vec3 shadow = Vec3::Zero();
    ASSERT_EQ(adcs::mrp_shadow(s, shadow), Status::ok);
    EXPECT_LE((r - shadow).norm(), 1e-14) << s.transpose();
    EXPECT_LE(r.norm(), 1.0);
  }
  // |sigma| = 1 exactly: either 180 deg representative.
  for (int k = 0; k < 10; ++k) {
    const Vec3 s = rng.unit3();
    const Vec3 r = adcs::dcm_to_mrp(adcs::mrp_to_dcm(s));
    EXPECT_LE(std::min((r - s).norm(), (r + s).norm()), 1e-14) << s.transpose();
  }
}

TEST(Mrp, QuaternionRoundTrip) {
  Rng rng(0x6003);
  for (int k = 0; k < kSamples; ++k) {
    QuaternionSF q = rng.quat();
    if (q.w() < -0.9) q = q.canonical();  // sigma = v/(1+w) is singular at w = -1
    const Vec3 s = adcs::quat_to_mrp(q);
    const QuaternionSF r = adcs::mrp_to_quat(s);
    EXPECT_LE(quat_dist(r, q), 1e-14);
    EXPECT_LE((r.scalar_first() - q.scalar_first()).norm(), 1e-14);  // in fact the same sign
    // Canonical quaternions give the short set.
    EXPECT_LE(adcs::quat_to_mrp(q.canonical()).norm(), 1.0);
  }
}

TEST(Mrp, ShadowSetIsTheSameAttitude) {
  Rng rng(0x6004);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 s = rng.mrp(0.05, 3.0);
    Vec3 sh = Vec3::Zero();
    ASSERT_EQ(adcs::mrp_shadow(s, sh), Status::ok);
    EXPECT_NEAR(sh.norm() * s.norm(), 1.0, 1e-14);
    EXPECT_LE(max_abs(adcs::mrp_to_dcm(sh) - adcs::mrp_to_dcm(s)), 1e-13);
    Vec3 back = Vec3::Zero();
    ASSERT_EQ(adcs::mrp_shadow(sh, back), Status::ok);
    EXPECT_LE((back - s).norm(), 1e-14 * (1.0 + s.norm()));
  }
}

TEST(Mrp, ShadowOfZeroAndNonFiniteLeaveOutputUntouched) {
  const Vec3 sentinel(7.0, 8.0, 9.0);
  Vec3 out = sentinel;
  EXPECT_EQ(adcs::mrp_shadow(Vec3::Zero(), out), Status::out_of_range);
  EXPECT_EQ(out, sentinel);
  for (const Vec3& bad : {Vec3(kNaN, 0, 0), Vec3(0.1, std::numeric_limits<double>::infinity(), 0),
                          Vec3(0, 0, -std::numeric_limits<double>::infinity())}) {
    out = sentinel;
    EXPECT_EQ(adcs::mrp_shadow(bad, out), Status::non_finite_input);
    EXPECT_EQ(out, sentinel);
  }
  // The smallest nonzero MRP still has a (huge but finite) shadow... or is refused; never Inf.
  for (double tiny : {1e-300, 1e-160, 1e-155}) {
    out = sentinel;
    const Status st = adcs::mrp_shadow(Vec3(tiny, 0, 0), out);
    if (st == Status::ok) {
      EXPECT_TRUE(adcs::all_finite(out)) << out.transpose();
    } else {
      EXPECT_EQ(st, Status::out_of_range);
      EXPECT_EQ(out, sentinel);
    }
  }
}

TEST(Mrp, ShadowSwitchKeepsNormAtMostOneAndTheAttitude) {
  Rng rng(0x6005);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 s0 = rng.mrp(0.0, 3.0);
    Vec3 s = s0;
    const bool switched = adcs::mrp_shadow_switch(s);
    EXPECT_EQ(switched, s0.norm() > 1.0);
    EXPECT_LE(s.norm(), 1.0);
    if (!switched) {
      EXPECT_EQ(s, s0);
    }
    EXPECT_LE(max_abs(adcs::mrp_to_dcm(s) - adcs::mrp_to_dcm(s0)), 1e-13);
    // A higher threshold (hysteresis) switches only beyond it, and still lands inside |s| <= 1.
    Vec3 t = s0;
    const bool switched_t = adcs::mrp_shadow_switch(t, 1.5);
    EXPECT_EQ(switched_t, s0.norm() > 1.5);
    EXPECT_LE(t.norm(), 1.5);
    if (switched_t) {
      EXPECT_LE(t.norm(), 1.0);
    }
  }
}

TEST(Mrp, GInverseAndOrthogonalityIdentity) {
  Rng rng(0x6006);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 s = rng.mrp(0.0, 3.0);
    const Mat3 G = adcs::mrp_G(s);
    const double d = (1.0 + s.squaredNorm()) / 4.0;
    EXPECT_LE(max_abs(G * adcs::mrp_G_inv(s) - Mat3::Identity()), 1e-14);
    EXPECT_LE(max_abs(adcs::mrp_G_inv(s) * G - Mat3::Identity()), 1e-14);
    EXPECT_LE(max_abs(G.transpose() * G - d * d * Mat3::Identity()), 1e-14 * d * d);
    // Truth: G from its definition written out (seed 001 eq. (6)).
    Mat3 Gt;
    Gt << 1 - s.squaredNorm() + 2 * s(0) * s(0), 2 * (s(0) * s(1) - s(2)), 2 * (s(0) * s(2) + s(1)),  //
        2 * (s(1) * s(0) + s(2)), 1 - s.squaredNorm() + 2 * s(1) * s(1), 2 * (s(1) * s(2) - s(0)),   //
        2 * (s(2) * s(0) - s(1)), 2 * (s(2) * s(1) + s(0)), 1 - s.squaredNorm() + 2 * s(2) * s(2);
    EXPECT_LE(max_abs(G - 0.25 * Gt), 1e-14 * (1 + s.squaredNorm()));
    const Vec3 w = rng.vec3();
    EXPECT_LE((adcs::mrp_rate(s, w) - G * w).norm(), 1e-15 * (1 + s.squaredNorm()));
  }
}

TEST(Mrp, GdotMatchesFiniteDifferences) {
  Rng rng(0x6007);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 s0 = rng.mrp(0.0, 2.0), sd = rng.vec3();
    const Mat3 num = central_diff([&](double t) { return adcs::mrp_G(s0 + t * sd); });
    const Mat3 ana = adcs::mrp_G_dot(s0, sd);
    EXPECT_LE(rel_err(num, ana), 1e-7) << "sigma = " << s0.transpose() << "\n" << num << "\n" << ana;
  }
}

TEST(Mrp, KinematicsMatchDcmFiniteDifferences) {
  // sigma_dot = G omega  <=>  d/dt C(sigma) = -[omega]x C.
  Rng rng(0x6008);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 s0 = rng.mrp(0.0, 1.5), sd = rng.vec3();
    const Mat3 C = adcs::mrp_to_dcm(s0);
    const Mat3 Cdot = central_diff([&](double t) { return adcs::mrp_to_dcm(s0 + t * sd); });
    const Vec3 omega = adcs::mrp_G_inv(s0) * sd;
    EXPECT_LE(rel_err(Cdot, Mat3(-adcs::skew(omega) * C)), 1e-7) << s0.transpose();
    // Reverse direction: the body rate seen by the DCM, mapped by G, gives sigma_dot back.
    const Vec3 omega_fd = adcs::vee(-Cdot * C.transpose());
    EXPECT_LE(rel_err(adcs::mrp_rate(s0, omega_fd), sd), 1e-7);
  }
}

TEST(Mrp, ShadowRateMatchesFiniteDifferencesAndKinematics) {
  Rng rng(0x6009);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 s0 = rng.mrp(0.2, 3.0), sd = rng.vec3();
    const Vec3 num = central_diff([&](double t) {
      Vec3 sh = Vec3::Zero();
      EXPECT_EQ(adcs::mrp_shadow(Vec3(s0 + t * sd), sh), Status::ok);
      return sh;
    });
    const Vec3 ana = adcs::mrp_shadow_rate(s0, sd);
    EXPECT_LE(rel_err(num, ana), 1e-7);
    // The shadow obeys the same kinematics with the same body rate.
    Vec3 sh = Vec3::Zero();
    ASSERT_EQ(adcs::mrp_shadow(s0, sh), Status::ok);
    const Vec3 omega = adcs::mrp_G_inv(s0) * sd;
    EXPECT_LE(rel_err(ana, Vec3(adcs::mrp_G(sh) * omega)), 1e-12);
  }
}

TEST(Mrp, SubtractIsTheRelativeAttitude) {
  Rng rng(0x600a);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 s_bn = rng.mrp(0.0, 1.0), s_rn = rng.mrp(0.0, 1.0);
    const Vec3 s_br = adcs::mrp_subtract(s_bn, s_rn);
    EXPECT_LE(s_br.norm(), 1.0 + 1e-15);
    const Mat3 C_br = adcs::mrp_to_dcm(s_bn) * adcs::mrp_to_dcm(s_rn).transpose();
    EXPECT_LE(max_abs(adcs::mrp_to_dcm(s_br) - C_br), 1e-14);
    EXPECT_LE(adcs::mrp_subtract(s_bn, s_bn).norm(), 1e-15);
    EXPECT_LE((adcs::mrp_subtract(s_bn, Vec3::Zero()) - s_bn).norm(), 1e-14);
    // Reversed order gives the inverse rotation: sigma_RB = -sigma_BR (short set, away from 180 deg).
    if (s_br.norm() < 0.99) {
      EXPECT_LE((adcs::mrp_subtract(s_rn, s_bn) + s_br).norm(), 1e-14);
    }
    // Long-set inputs give the same answer as their shadows.
    if (s_bn.norm() > 0.1) {
      Vec3 sh = Vec3::Zero();
      ASSERT_EQ(adcs::mrp_shadow(s_bn, sh), Status::ok);
      EXPECT_LE(max_abs(adcs::mrp_to_dcm(adcs::mrp_subtract(sh, s_rn)) - C_br), 1e-13);
    }
  }
}

TEST(Mrp, PrincipalAngleOfAxisAngle) {
  Rng rng(0x600b);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 a = rng.unit3();
    const double phi = rng.uniform(0.0, kPi);
    const QuaternionSF q = QuaternionSF::from_axis_angle(a, phi);
    const Vec3 s = adcs::quat_to_mrp(q);
    EXPECT_NEAR(adcs::mrp_principal_angle(s), phi, 1e-14);
    EXPECT_LE((s - a * std::tan(phi / 4.0)).norm(), 1e-15);
    // Long way round (pi, 1.9 pi): the non-canonical quaternion gives the long set.
    const double phi_long = rng.uniform(kPi, 1.9 * kPi);
    const QuaternionSF ql = QuaternionSF::from_axis_angle(a, phi_long);
    EXPECT_NEAR(adcs::mrp_principal_angle(adcs::quat_to_mrp(ql)), phi_long, 1e-13);
    EXPECT_NEAR(adcs::mrp_principal_angle(adcs::quat_to_mrp(ql.canonical())), 2 * kPi - phi_long, 1e-13);
  }
  EXPECT_EQ(adcs::mrp_principal_angle(Vec3::Zero()), 0.0);
  EXPECT_NEAR(adcs::mrp_principal_angle(Vec3(0, 0, 1)), kPi, 1e-15);
}

// =============================================================================================
// Euler angles: x-y-z (seed 002 eq. (3), spec §B.2) and 3-2-1

// Schaub & Junkins 1-2-3 DCM written out elementwise (theta1 = phi, theta2 = theta, theta3 = psi).
Mat3 schaub_123(const Vec3& a) {
  const double c1 = std::cos(a(0)), s1 = std::sin(a(0)), c2 = std::cos(a(1)), s2 = std::sin(a(1));
  const double c3 = std::cos(a(2)), s3 = std::sin(a(2));
  Mat3 C;
  C << c2 * c3, c1 * s3 + s1 * s2 * c3, s1 * s3 - c1 * s2 * c3,  //
      -c2 * s3, c1 * c3 - s1 * s2 * s3, s1 * c3 + c1 * s2 * s3,  //
      s2, -s1 * c2, c1 * c2;
  return C;
}

// Schaub & Junkins 3-2-1 DCM elementwise, ypr = [psi, theta, phi].
Mat3 schaub_321(const Vec3& ypr) {
  const double cp = std::cos(ypr(0)), sp = std::sin(ypr(0)), ct = std::cos(ypr(1)), st = std::sin(ypr(1));
  const double cf = std::cos(ypr(2)), sf = std::sin(ypr(2));
  Mat3 C;
  C << ct * cp, ct * sp, -st,                                    //
      sf * st * cp - cf * sp, sf * st * sp + cf * cp, sf * ct,  //
      cf * st * cp + sf * sp, cf * st * sp - sf * cp, cf * ct;
  return C;
}

// Schaub's B(3-2-1): ypr_dot = B omega.
Mat3 schaub_B321(const Vec3& ypr) {
  const double ct = std::cos(ypr(1)), st = std::sin(ypr(1)), cf = std::cos(ypr(2)), sf = std::sin(ypr(2));
  Mat3 B;
  B << 0, sf, cf,  //
      0, cf * ct, -sf * ct,  //
      ct, sf * st, cf * st;
  return B / ct;
}

TEST(Euler123, DcmMatchesSpecProductAndSchaub) {
  Rng rng(0x7001);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 a = rng.euler(kPi / 2);
    const Mat3 C = adcs::euler123_to_dcm(a);
    EXPECT_TRUE(is_rotation(C));
    EXPECT_LE(max_abs(C - spec_R3(a(2)) * spec_R2(a(1)) * spec_R1(a(0))), 1e-15);
    EXPECT_LE(max_abs(C - schaub_123(a)), 1e-15);
  }
}

TEST(Euler123, DcmRoundTrip) {
  Rng rng(0x7002);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 a = rng.euler();
    const Vec3 r = adcs::dcm_to_euler123(adcs::euler123_to_dcm(a));
    EXPECT_NEAR(wrap(r(0) - a(0)), 0.0, 1e-13);
    EXPECT_NEAR(r(1), a(1), 1e-12);  // asin loses a little near 89 deg
    EXPECT_NEAR(wrap(r(2) - a(2)), 0.0, 1e-13);
    EXPECT_LE(std::abs(r(1)), kPi / 2);
  }
  // At gimbal lock only phi + psi (theta = +90 deg) is defined; the DCM still round trips.
  for (double pitch : {kPi / 2, -kPi / 2}) {
    const Vec3 a(0.3, pitch, -0.4);
    const Mat3 C = adcs::euler123_to_dcm(a);
    const Vec3 r = adcs::dcm_to_euler123(C);
    EXPECT_TRUE(adcs::all_finite(r));
    EXPECT_LE(max_abs(adcs::euler123_to_dcm(r) - C), 1e-7);
  }
}

TEST(Euler123, KinematicsMatchDcmFiniteDifferences) {
  // omega = G(theta) theta_dot  <=>  d/dt C(theta(t)) = -[omega]x C.   seed 002 eq. (3)
  Rng rng(0x7003);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 a = rng.euler(), ad = rng.vec3();
    const Mat3 C = adcs::euler123_to_dcm(a);
    const Mat3 Cdot = central_diff([&](double t) { return adcs::euler123_to_dcm(a + t * ad); });
    const Vec3 omega = adcs::euler123_G(a) * ad;
    EXPECT_LE(rel_err(Cdot, Mat3(-adcs::skew(omega) * C)), 1e-7) << a.transpose();
    Mat3 F = Mat3::Zero();
    ASSERT_EQ(adcs::euler123_F(a, F), Status::ok);
    const Vec3 omega_fd = adcs::vee(-Cdot * C.transpose());
    EXPECT_LE(rel_err(Vec3(F * omega_fd), ad), 1e-7);
  }
}

TEST(Euler123, FInvertsGAndGdotMatchesFiniteDifferences) {
  Rng rng(0x7004);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 a = rng.euler(), ad = rng.vec3();
    Mat3 F = Mat3::Zero();
    ASSERT_EQ(adcs::euler123_F(a, F), Status::ok);
    const Mat3 G = adcs::euler123_G(a);
    const double sec = 1.0 / std::cos(a(1));
    EXPECT_LE(max_abs(F * G - Mat3::Identity()), 1e-14 * sec);
    EXPECT_LE(max_abs(G * F - Mat3::Identity()), 1e-14 * sec);
    const Mat3 num = central_diff([&](double t) { return adcs::euler123_G(a + t * ad); });
    EXPECT_LE(rel_err(num, adcs::euler123_G_dot(a, ad)), 1e-7);
    // G_dot is linear in theta_dot and independent of phi.
    EXPECT_LE(max_abs(adcs::euler123_G_dot(a, 2.0 * ad) - 2.0 * adcs::euler123_G_dot(a, ad)), 1e-15);
    EXPECT_EQ(adcs::euler123_G_dot(Vec3(0.0, a(1), a(2)), ad), adcs::euler123_G_dot(a, ad));
  }
}

TEST(Euler123, FIsSingularAtGimbalLockAndLeavesOutputUntouched) {
  const Mat3 sentinel = Mat3::Constant(42.0);
  for (double pitch : {kPi / 2, -kPi / 2, 3 * kPi / 2, kPi / 2 + 1e-10}) {
    Mat3 F = sentinel;
    EXPECT_EQ(adcs::euler123_F(Vec3(0.3, pitch, -0.7), F), Status::singular) << pitch;
    EXPECT_EQ(F, sentinel);
  }
  // Just outside the documented threshold the inverse is still returned, and finite.
  Mat3 F = sentinel;
  const double pitch_ok = kPi / 2 - 10.0 * adcs::kEulerSingularCos;
  EXPECT_EQ(adcs::euler123_F(Vec3(0.3, pitch_ok, -0.7), F), Status::ok);
  EXPECT_TRUE(adcs::all_finite(F));
  EXPECT_LE(max_abs(F * adcs::euler123_G(Vec3(0.3, pitch_ok, -0.7)) - Mat3::Identity()), 1e-6);
  // G itself is defined everywhere.
  EXPECT_TRUE(adcs::all_finite(adcs::euler123_G(Vec3(0.3, kPi / 2, -0.7))));
}

TEST(Euler, FRejectsNonFiniteAnglesAndLeavesOutputUntouched) {
  // Status contract (core/status.hpp): NaN/Inf input -> non_finite_input, outputs held. Before
  // the fix a NaN pitch was reported as `singular` (cos(NaN) fails the gimbal-lock test).
  const Mat3 sentinel = Mat3::Constant(5.0);
  const double inf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    for (double bad : {kNaN, inf, -inf}) {
      Vec3 a(0.1, 0.2, 0.3);
      a(i) = bad;
      Mat3 F = sentinel;
      EXPECT_EQ(adcs::euler123_F(a, F), Status::non_finite_input) << i << " " << bad;
      EXPECT_EQ(F, sentinel);
      EXPECT_EQ(adcs::euler321_F(a, F), Status::non_finite_input) << i << " " << bad;
      EXPECT_EQ(F, sentinel);
    }
  }
}

TEST(Euler321, DcmMatchesSchaubAndRoundTrips) {
  Rng rng(0x7101);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 ypr = rng.euler();
    const Mat3 C = adcs::euler321_to_dcm(ypr);
    EXPECT_TRUE(is_rotation(C));
    EXPECT_LE(max_abs(C - schaub_321(ypr)), 1e-15);
    EXPECT_LE(max_abs(C - spec_R1(ypr(2)) * spec_R2(ypr(1)) * spec_R3(ypr(0))), 1e-15);
    const Vec3 r = adcs::dcm_to_euler321(C);
    EXPECT_NEAR(wrap(r(0) - ypr(0)), 0.0, 1e-13);
    EXPECT_NEAR(r(1), ypr(1), 1e-12);
    EXPECT_NEAR(wrap(r(2) - ypr(2)), 0.0, 1e-13);
  }
}

TEST(Euler321, KinematicsFAndGMatchSchaubAndFiniteDifferences) {
  Rng rng(0x7102);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 ypr = rng.euler(), yd = rng.vec3();
    const Mat3 C = adcs::euler321_to_dcm(ypr);
    const Mat3 Cdot = central_diff([&](double t) { return adcs::euler321_to_dcm(ypr + t * yd); });
    const Vec3 omega = adcs::euler321_G(ypr) * yd;
    EXPECT_LE(rel_err(Cdot, Mat3(-adcs::skew(omega) * C)), 1e-7) << ypr.transpose();
    Mat3 F = Mat3::Zero();
    ASSERT_EQ(adcs::euler321_F(ypr, F), Status::ok);
    const double sec = 1.0 / std::cos(ypr(1));
    EXPECT_LE(max_abs(F - schaub_B321(ypr)), 1e-15 * sec);
    EXPECT_LE(max_abs(F * adcs::euler321_G(ypr) - Mat3::Identity()), 1e-14 * sec);
    const Vec3 omega_fd = adcs::vee(-Cdot * C.transpose());
    EXPECT_LE(rel_err(Vec3(F * omega_fd), yd), 1e-7);
  }
  const Mat3 sentinel = Mat3::Constant(-3.0);
  for (double pitch : {kPi / 2, -kPi / 2}) {
    Mat3 F = sentinel;
    EXPECT_EQ(adcs::euler321_F(Vec3(0.2, pitch, 0.1), F), Status::singular);
    EXPECT_EQ(F, sentinel);
  }
}

TEST(Euler, MrpRoundTripsThroughTheDcm) {
  Rng rng(0x7201);
  for (int k = 0; k < kSamples; ++k) {
    // Euler -> DCM -> MRP -> DCM -> Euler, both sequences.
    const Vec3 a = rng.euler();
    const Vec3 s = adcs::dcm_to_mrp(adcs::euler123_to_dcm(a));
    EXPECT_LE(s.norm(), 1.0);
    const Vec3 r = adcs::dcm_to_euler123(adcs::mrp_to_dcm(s));
    EXPECT_NEAR(wrap(r(0) - a(0)), 0.0, 1e-12);
    EXPECT_NEAR(r(1), a(1), 1e-11);
    EXPECT_NEAR(wrap(r(2) - a(2)), 0.0, 1e-12);
    const Vec3 s321 = adcs::dcm_to_mrp(adcs::euler321_to_dcm(a));
    const Vec3 r321 = adcs::dcm_to_euler321(adcs::mrp_to_dcm(s321));
    EXPECT_NEAR(wrap(r321(0) - a(0)), 0.0, 1e-12);
    EXPECT_NEAR(r321(1), a(1), 1e-11);
    EXPECT_NEAR(wrap(r321(2) - a(2)), 0.0, 1e-12);

    // MRP -> DCM -> Euler -> DCM -> MRP (away from gimbal lock and from 180 deg).
    const Vec3 s0 = rng.mrp(0.0, 0.99);
    const Mat3 C0 = adcs::mrp_to_dcm(s0);
    if (std::abs(C0(2, 0)) < std::sin(89.0 * kDeg)) {
      EXPECT_LE((adcs::dcm_to_mrp(adcs::euler123_to_dcm(adcs::dcm_to_euler123(C0))) - s0).norm(), 1e-12);
    }
    if (std::abs(C0(0, 2)) < std::sin(89.0 * kDeg)) {
      EXPECT_LE((adcs::dcm_to_mrp(adcs::euler321_to_dcm(adcs::dcm_to_euler321(C0))) - s0).norm(), 1e-12);
    }
  }
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
