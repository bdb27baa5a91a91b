// SPDX-License-Identifier: GPL-2.0-or-later
// FFTW wisdom (core/fft_engine.hpp): a shape whose measured plans were saved and imported
// into a process that had forgotten them is planned from that wisdom alone, timing no
// candidate (counted by fft_planner::plan_counts()); damaged wisdom, what is not a regular
// file and a file larger than any wisdom are refused with Error(io) naming the file, and what
// the process knew before is kept.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

#include "core/error.hpp"
#include "core/fft_engine.hpp"
#include "core/fft_planner.hpp"

namespace {

// A shape no other test plans, so that its plans start unknown.
constexpr std::int64_t nx = 54, ny = 38;

void forget_wisdom() {
  std::lock_guard<std::mutex> lock(asp::fft_planner::mutex());
  fftw_forget_wisdom();
}

// How plans of the shape were made by one measured RealFft.
asp::fft_planner::PlanCounts plans_of_one_grid() {
  const asp::fft_planner::PlanCounts before = asp::fft_planner::plan_counts();
  const asp::RealFft fft(nx, ny, asp::FftPlanning::measure);
  const asp::fft_planner::PlanCounts after = asp::fft_planner::plan_counts();
  return {after.from_wisdom - before.from_wisdom, after.planned - before.planned};
}

std::string file_named(const char *name) {
  return ::testing::TempDir() + "asperity_wisdom_" + std::to_string(getpid()) + "_" + name;
}

void expect_refused(const std::string &path, const char *problem) {
  try {
    asp::import_fft_wisdom(path);
    ADD_FAILURE() << path << " was imported";
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), asp::Status::io);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
  }
}

TEST(FftWisdom, ARoundTripPlansNothing) {
  forget_wisdom();
  asp::fft_planner::PlanCounts made = plans_of_one_grid();
  EXPECT_EQ(made.planned, 2);  // r2c and c2r, measured
  EXPECT_EQ(made.from_wisdom, 0);
  made = plans_of_one_grid();  // the same process now knows them
  EXPECT_EQ(made.planned, 0);
  EXPECT_EQ(made.from_wisdom, 2);

  const std::string saved = file_named("saved");
  asp::export_fft_wisdom(saved);
  forget_wisdom();
  made = plans_of_one_grid();  // forgotten: measured again
  EXPECT_EQ(made.planned, 2);
  forget_wisdom();
  asp::import_fft_wisdom(saved);
  made = plans_of_one_grid();  // imported: nothing timed
  EXPECT_EQ(made.planned, 0);
  EXPECT_EQ(made.from_wisdom, 2);
  std::remove(saved.c_str());
}

TEST(FftWisdom, BadFilesAreRefusedAndWhatWasKnownIsKept) {
  forget_wisdom();
  plans_of_one_grid();  // the shape is known from here on

  const std::string damaged = file_named("damaged");
  std::ofstream(damaged) << "(fftw-3.3.10 fftw_wisdom #x12 garbage (((";
  expect_refused(damaged, "not wisdom of this FFTW");
  const std::string foreign = file_named("foreign");
  std::ofstream(foreign) << "(fftw-2.9.9 fftw_wisdom\n)\n";
  expect_refused(foreign, "not wisdom of this FFTW");
  expect_refused("/dev/null", "not a regular file");
  expect_refused(::testing::TempDir(), "not a regular file");
  expect_refused(file_named("missing"), "missing");
  const std::string huge = file_named("huge");
  { std::ofstream(huge) << "(fftw-"; }
  ASSERT_EQ(truncate(huge.c_str(), asp::largest_wisdom_bytes + 1), 0);
  expect_refused(huge, "larger than");

  const asp::fft_planner::PlanCounts made = plans_of_one_grid();
  EXPECT_EQ(made.planned, 0);
  EXPECT_EQ(made.from_wisdom, 2);
  for (const std::string &path : {damaged, foreign, huge}) std::remove(path.c_str());
}

}  // namespace
