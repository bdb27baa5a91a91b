// SPDX-License-Identifier: GPL-2.0-or-later
// A fresh file name for the running test, in a directory of this process that is removed at
// exit (by this process only: forked children that leave with _exit keep it).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

inline std::string temp_path(const std::string &name) {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() /
             ("asperity_io_tests_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  static struct Cleanup {
    ~Cleanup() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  } cleanup;
  const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
  return (dir / (std::string(info ? info->name() : "x") + "_" + name)).string();
}
