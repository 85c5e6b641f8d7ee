#pragma once
// The published figures of the paper's evaluation (§4) and summary (§5), as
// printed: the targets `capsim repro` sets its runs beside.

#include <array>

namespace capsim::sim::paper {

// Table 4-2: M380 seconds, primary rays, against divisions per axis.
inline constexpr std::array<int, 7> kTable42Divisions = {1, 2, 4, 8, 16, 32, 48};
inline constexpr std::array<int, 5> kTable42Objects = {16, 512, 1000, 4096, 6859};
inline constexpr double kTable42Seconds[5][7] = {
    {102, 39, 23, 20, 21, 25, 30},
    {825, 212, 68, 34, 28, 31, 36},
    {1573, 450, 126, 59, 38, 38, 43},
    {13094, 2856, 678, 211, 104, 96, 101},
    {32621, 7306, 1557, 482, 219, 162, 163},
};

// Table 4-3: PISTON on the M380, seconds by process (Table 4-3's order:
// intersection, 3DDDA incl. set-up, CSG evaluation, voxel generation, other).
inline constexpr std::array<int, 3> kTable43Divisions = {2, 16, 32};
inline constexpr double kTable43Seconds[3][5] = {
    {108.5, 3.4, 4.9, 0.2, 5.5},
    {11.4, 5.1, 4.5, 0.5, 5.8},
    {7.8, 6.9, 6.0, 2.3, 5.1},
};
inline constexpr double kTable43Percent[3][5] = {
    {84.4, 2.7, 3.8, 0.1, 4.2},
    {34.2, 15.4, 13.4, 1.6, 17.4},
    {23.0, 20.4, 17.6, 6.6, 14.8},
};
inline constexpr double kTable43Total[3] = {128.5, 33.4, 34.1};
// Its shares add up to 95, 82 and 82 % (its rows do not sum to its totals):
// share k of column i as a percentage of the column's own sum.
inline constexpr double table_4_3_renormalised_percent(int i, int k) {
  double sum = 0;
  for (double p : kTable43Percent[i]) sum += p;
  return 100 * kTable43Percent[i][k] / sum;
}

// Table 4-4: 64 cells, seconds: Max, Min and d (%) in line and in dot mode.
struct SpreadFigures {
  double max, min, d;
};
struct Table44Row {
  const char* model;
  int objects;
  SpreadFigures line, dot;
};
inline constexpr std::array<Table44Row, 3> kTable44 = {{
    {"BALLS", 125, {93, 84, 9.7}, {88, 86, 2.3}},
    {"CHESS", 143, {324, 259, 20.1}, {294, 281, 4.4}},
    {"CAD", 185, {792, 637, 19.6}, {691, 667, 3.5}},
}};

// Graph 4-3: CHESS, dot mode, 64 cells against 16.
inline constexpr double kGraph43DotSpeedAt64 = 3.96;

// Table 4-5: DISB, 64 frames: total seconds and max deviation (%).
struct Table45Row {
  const char* processing;
  double seconds, max_deviation;
};
inline constexpr std::array<Table45Row, 3> kTable45 = {{
    {"no antialiasing", 1336, 6.5},
    {"antialiasing", 4626, 60.4},
    {"frame-averaged antialiasing", 2595, 8.8},
}};

// Table 5-1: CAP (64 cells) against the M380, seconds.
struct Table51Row {
  const char* model;
  int objects;
  double cap, m380;
};
inline constexpr std::array<Table51Row, 4> kTable51 = {{
    {"CHESS", 144, 155, 128},
    {"BALLS", 125, 72, 60},
    {"PISTON", 179, 40, 33},
    {"CAD", 178, 20, 20},
}};

// Table 4-1: the M380's sphere test and 3DDDA set-up, microseconds.
inline constexpr double kM380SphereTestUs = 18.2;
inline constexpr double kM380DdaSetupUs = 33.8;

// Table 4-1: the M380 / CAP ratio of the sphere test, and their median over
// the table's eight operations: a CAP cell is about 164 times slower.
inline constexpr double kCapOverM380 = 164;

}  // namespace capsim::sim::paper
