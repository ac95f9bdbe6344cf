// One empty row for the baseline program (replay_baseline.cpp).
#pragma once
namespace replay_data {
inline constexpr int kSteps = 1;
inline constexpr int kWidth = 1;
alignas(8) static const double kRows[1][1] = {{0.0}};
}  // namespace replay_data
