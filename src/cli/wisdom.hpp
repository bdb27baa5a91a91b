// SPDX-License-Identifier: GPL-2.0-or-later
// The command's FFTW wisdom file: what measured FFT planning has learnt, kept between runs so
// that a later run on a grid shape met before plans nothing. It is read before the first grid
// is made and written after the solves when the planning measured (measure or patient); the
// file is replaced by renaming a complete one over it, so that runs at the same time never
// read half of one. Nothing here stops a run: a file that cannot be read or written is a
// note on standard error, and the run plans afresh.
#pragma once

#include <string>

#include "contact.hpp"

namespace cli {

// The wisdom file: --wisdom PATH, else $XDG_CACHE_HOME/asperity/fftw-wisdom when that
// variable holds an absolute path, else $HOME/.cache/asperity/fftw-wisdom; "" for none
// (--no-wisdom, or neither variable set).
std::string wisdom_path(const ComputeOptions &compute);

// Adds the wisdom of the file to the process's. A default file that does not exist yet (the
// first run) is passed over in silence; one given with --wisdom gets a note. A file the
// library refuses (not a regular file, too large, damaged, written by another FFTW) gets one
// note with the library's reason, and the process's wisdom is left as it was.
void read_wisdom(const ComputeOptions &compute);

// Writes the process's wisdom to the file when the planning measured, making its directory
// (and the directories above it that are missing, mode 0700) on the way. A path that exists
// and is not a regular file is left alone (reading it has said so).
void write_wisdom(const ComputeOptions &compute);

}  // namespace cli
