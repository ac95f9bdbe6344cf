// main() of a replay program, built once per System and side with
//   ADCS_REPLAY_API     the System's Api (replay::kHybrid, kPpc, kSe3, kDragFree, kBaseline)
//   ADCS_REPLAY_INPUTS  the generated header of its recorded rows ("replay_inputs_<name>.hpp",
//                       from record_inputs; the baseline uses a one-row header of its own)
// Host: replay_<name>_host; target: replay_<name>.elf (tests/target/CMakeLists.txt).
#include "replay_runtime.hpp"
#include ADCS_REPLAY_INPUTS

int main(int argc, char** argv) {
  return replay::run(ADCS_REPLAY_API, argc, argv, &replay_data::kRows[0][0], replay_data::kWidth,
                     replay_data::kSteps);
}
