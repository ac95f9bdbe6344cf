// Explicit instantiation of every class template of include/adcs (and the function templates of
// the per-step kernels) with the sizes the library is used at (tests/target/instantiate_*.cpp,
// the scenarios). The 27/36-state function templates (expm<36>, zoh_discretize<27, 9>,
// keep_psd<27>) are left to the drag-free tests that instantiate them at those sizes: explicitly
// instantiated here they cost g++ minutes of compile time for no extra line. A header's template code is only compiled, and so only seen by gcov, where it
// is instantiated: this TU makes every member of every class template count in the coverage
// report (tools/coverage.sh), so an untested member shows as uncovered instead of invisible.
//
// Only in the coverage build (preset "coverage" defines ADCS_INSTANTIATE_ALL): instantiating every
// member of the 27-state filters, the SE(3)/VSCMG plants and the controllers costs g++ ~5 CPU
// minutes for this one TU (measured, -fsyntax-only already), which the Release and ASan builds
// of CI do not need: there the file is empty. Its construction test
// (InstantiateAll.DefaultParametersGiveTheDocumentedConstructionStatus) lives in
// test_parameter_validation.cpp, which instantiates the same constructors anyway: here it cost
// its unity batch ~30 clang+ASan CPU-s of its own (seed 001's gain design, the 27-state filter).
#ifdef ADCS_INSTANTIATE_ALL
#include "adcs/adcs.hpp"
#endif

#ifdef ADCS_INSTANTIATE_ALL
namespace adcs {
// core/signals.hpp
template struct WheelTorques<4>;
template struct VscmgRates<4, 3>;
template struct VscmgRates<4, 0>;
template struct VscmgState<4, 3>;
template struct VscmgState<4, 0>;
template struct AccelerometerSample<3>;
// actuator/
template struct RwAllocationParams<4>;
template class RwTorqueAllocator<4>;
template struct SaturationParams<6>;
template class Saturation<6>;
template struct CompositeQuantizerParams<6>;
template class CompositeQuantizer<6>;
template struct SaturatedQuantizerParams<6>;
template class SaturatedQuantizer<6>;
template struct VscmgSteeringParams<4, 0>;
template struct VscmgSteeringInput<4, 0>;
template class VscmgSteering<4, 0>;
template Status saturate_then_quantize<6>(const Vec<6>&, const Vec<6>&, CompositeQuantizer<6>&, Vec<6>&,
                                          std::uint32_t*) noexcept;
template int saturate_each<7>(Vec<7>&, const Vec<7>&) noexcept;
template int saturate_each<9>(Vec<9>&, const Vec<9>&) noexcept;
template Status steer<7>(const Mat<3, 7>&, const Vec3&, const SteeringParams&, Vec<7>&, SteeringInfo*) noexcept;
template Status steer_available<7>(const Mat<3, 7>&, const Vec3&, const SteeringParams&, ActuatorMask, Vec<7>&,
                                   SteeringInfo*) noexcept;
template Status steer_escape<4>(const Mat<3, 4>&, const Vec3&, const EscapeSteeringParams&, double, Vec<4>&,
                                SteeringInfo*) noexcept;
template struct VscmgGeometry<4, 0>;
template Status set_cmg_pyramid<4, 0>(double, double, VscmgGeometry<4, 0>&) noexcept;
template Status wheel_pyramid_axes<4>(double, Mat<3, 4>&) noexcept;
// adapt/
template struct PpcParams<3>;
template struct PpcSample<3>;
template class PrescribedPerformance<3>;
template struct RbfLayerParams<6, 7>;
template class RbfLayer<6, 7>;
template struct RbfCompensatorParams<6, 7, 3>;
template class RbfCompensator<6, 7, 3>;
template Mat<7, 3> rbf_weight_step<7, 3>(const Mat<7, 3>&, const Vec<7>&, const Vec<3>&, const Vec<3>&, double,
                                         double) noexcept;
template Status smooth_projection<6>(const Vec<6>&, const Vec<6>&, const ProjectionParams&, Vec<6>&, bool*) noexcept;
template Status smooth_projection<3>(const Vec<3>&, const Vec<3>&, const ProjectionParams&, Vec<3>&, bool*) noexcept;
template bool radial_safeguard<6>(Vec<6>&, double) noexcept;
template bool radial_safeguard<3>(Vec<3>&, double) noexcept;
// control/
template struct MrpPdParams<4>;
template struct MrpPdInput<4>;
template class MrpPd<4>;
template class MrpPd<3>;
template struct HybridAdaptiveParams<4, 3>;
template struct HybridAdaptiveInput<4, 3>;
template struct HybridAdaptiveDiagnostics<4, 3>;
template class HybridAdaptive<4, 3>;
template struct PidParams<1>;
template struct PidInput<1>;
template struct PidOutput<1>;
template struct PidDiagnostics<1>;
template class Pid<1>;
template class Pid<3>;
template Vec<6> sig<6>(const Vec<6>&, double) noexcept;
// estimate/
template struct EskfParams<27, 9, 9, 9>;
template struct EskfInput<9, 9, 9>;
template struct EskfOutput<27>;
template class Eskf<27, 9, 9, 9>;
template class Eskf<18, 9, 9, 6>;  // the two blocks of DragFreeEskf
template class Eskf<9, 9, 9, 3>;
template class PartitionedFilter<Eskf<18, 9, 9, 6>, Eskf<9, 9, 9, 3>>;  // DragFreeEskfJoseph
template class EskfUd<18, 9, 9, 6, 12>;  // the two blocks of DragFreeEskf
template class EskfUd<9, 9, 9, 3, 6>;
template class PartitionedFilter<EskfUd<18, 9, 9, 6, 12>, EskfUd<9, 9, 9, 3, 6>>;
template bool ud_factorize<5>(const Mat<5, 5>&, UdFactors<5>&) noexcept;
template bool keep_psd<3>(Mat<3, 3>&) noexcept;
// math/
template Status expm<3>(const Mat<3, 3>&, Mat<3, 3>&) noexcept;
template Status zoh_discretize<3, 1>(const Mat<3, 3>&, const Mat<3, 1>&, double, Mat<3, 3>&, Mat<3, 1>&) noexcept;
template Status right_pinv_solve<3, 7>(const Mat<3, 7>&, const Vec<3>&, Vec<7>&, PinvInfo*) noexcept;
template Status right_pinv<3, 4>(const Mat<3, 4>&, Mat<4, 3>&, PinvInfo*) noexcept;
template Status damped_right_pinv_solve<3, 7>(const Mat<3, 7>&, const Vec<3>&, Vec<7>&, const DampingParams&,
                                              PinvInfo*) noexcept;
template Status solve_continuous_lyapunov<6>(const Mat<6, 6>&, const Mat<6, 6>&, Mat<6, 6>&) noexcept;
template Status place_double_integrator<3>(const AxisPoles<3>&, Mat<3, 6>&) noexcept;
template Mat<6, 6> double_integrator_closed_loop<3>(const Mat<3, 6>&) noexcept;
// plant/
template struct RigidBodyRwParams<4>;
template class RigidBodyRw<4>;
template struct FlexibleSpacecraftParams<2, 4>;
template class FlexibleSpacecraft<2, 4>;
template struct VscmgGeometry<4, 3>;
template struct VscmgDeviation<4, 3>;
template struct VscmgParams<4, 3>;
template class VscmgFullPlant<4, 3>;
template class VscmgCtrlPlant<4, 3>;
template VscmgGeometry<4, 3> apply_deviation<4, 3>(const VscmgGeometry<4, 3>&, const VscmgDeviation<4, 3>&) noexcept;
template VscmgDeviation<4, 3> rigid_mounting_deviation<4, 3>(const VscmgGeometry<4, 3>&, const Mat<3, 4>&,
                                                            const Mat<3, 3>&) noexcept;
}  // namespace adcs
#endif  // ADCS_INSTANTIATE_ALL
