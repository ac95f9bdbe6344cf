#pragma once
// The small interface between a replayed flight System and the code around it (the replay
// driver, the input recorder), so that the heavy Eigen/adcs code of each System is compiled once
// per side: in its replay_<name>.cpp ("core"), which the host replay, the recorder and the
// target replay link. This header includes no Eigen.
//
// A System (replay_<name>.hpp, included by its core only) provides:
//   static constexpr const char* kName; static constexpr int kInputWidth; double kPeriod;
//   static constexpr Column kColumns[]; static constexpr int kCommandSize; static constexpr int kParts;
//   adcs::Status init_status() const;
//   void step(const double* row) noexcept;               one control sample (what is measured)
//   void step_part(int part, const double* row) noexcept; the sample in kParts pieces (recorder)
//   void outputs(double* values) const noexcept;         kColumns values after the last step
//   void command(double* u) const noexcept;              the command the loop applies (recorder)
// and optionally, for a per-stage cost (replay_runtime.hpp, CostMeter; without them: one stage):
//   static constexpr int kCostStages = N;                 2 <= N <= kMaxCostStages
//   static constexpr const char* kStageNames[N];          one word each
//   void step_stages(int n, const double* row) noexcept;  the first n stages of step() only;
//                                                        step(row) is step_stages(N, row)
#include "adcs/core/status.hpp"

namespace replay {

//! One output column: name and the scale below which differences count absolutely: the
//! comparison uses |host - target| / max(|host|, scale); scale 0 = must match exactly (statuses,
//! counters, printed as integers).
struct Column {
  const char* name;
  double scale;
};

constexpr int kMaxCostStages = 4;

struct Api {
  const char* name;
  int input_width;       //!< doubles per recorded row
  double period_s;       //!< [s] control period of the loop the rows come from
  const Column* columns;
  int num_columns;
  int command_size;
  int parts;             //!< 1, or 2 when the loop feeds part of a row after the first part ran
  adcs::Status (*init_status)();
  void (*step)(const double* row);                 //!< one step() of the live System
  void (*step_part)(int part, const double* row);  //!< recorder: parts 0..parts-1 = one step()
  void (*outputs)(double* values);
  void (*command)(double* u);
  int cost_stages;                //!< stages of step() measured separately (1: step() as a whole)
  const char* const* stage_names;  //!< cost_stages names
  //! Target cost mode (replay_runtime.hpp, CostMeter); null on the host.
  bool (*calibrate)(const double* row, char* report);
  long long (*measure)(const double* row);
  //! Target cost mode: instructions of the first n stages (1 <= n < cost_stages); null on the host.
  long long (*measure_prefix)(int n, const double* row);
};

// Defined by the cores replay_<name>.cpp.
extern const Api kHybrid;    // seed 001
extern const Api kPpc;       // seed 002
extern const Api kSe3;       // seed 003
extern const Api kDragFree;  // seed 004
extern const Api kBaseline;  // empty System (target size baseline)
extern const Api kAttitude;   // MrpPd<4> + RwTorqueAllocator<4>, double (Cortex-M7)
extern const Api kAttitudeF;  // the same in float (Cortex-M4F; issue 19)
extern const Api kPpcF;       // seed 002 in float (Cortex-M4F; issue 19)
extern const Api kHybridF;    // seed 001 in float (Cortex-M4F; issue 19)
extern const Api kSe3F;       // seed 003 (the BsPdTC law) in float (Cortex-M4F; issue 19)
extern const Api kDragFreeF;  // seed 004's sample in float (Cortex-M4F; issue 19)
extern const Api kAtcF;       // seed 002's ATC baseline in float (Cortex-M4F; issue 19)
extern const Api kEsoAdrcF;   // the ESO-based ADRC on seed 002's vehicle in float (Cortex-M4F)
extern const Api kSe3FtsmcF;  // seed 003's FTSMC baseline in float (Cortex-M4F; issue 19)

}  // namespace replay
