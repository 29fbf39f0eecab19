// `arbc run --status`: the live view of the arbitrated ports (runtime/port_status.h) on the
// terminal, a line per port, redrawn in place every RunOptions::status_period (250 ms) of run time.
// On a terminal the lines are cut to its width, so that the redraw (cursor up, line by line) stays
// in place; to a file or a pipe each view is written in full after a line with its instant.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "runtime/runtime.h"

namespace arbc::cli {

class StatusBoard {
 public:
  // `out`: where to draw; `terminal`: it is one (isatty), `columns` its width (0: unknown).
  StatusBoard(std::FILE* out, bool terminal, size_t columns)
      : out_(out), terminal_(terminal), columns_(columns) {}
  // The board of standard error (the end table and the verdict stay on standard output).
  static StatusBoard for_stderr();
  // Draws the view of instant `t`, over the last one on a terminal.
  void show(Nanos t, const std::vector<PortStatus>& ports);
  // Sets options.on_status to draw here.
  void attach(RunOptions& options);

 private:
  std::FILE* out_;
  bool terminal_;
  size_t columns_;
  size_t drawn_ = 0;  // lines of the last view on the terminal
};

}  // namespace arbc::cli
