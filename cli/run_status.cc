#include "cli/run_status.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include "core/duration_literal.h"

namespace arbc::cli {

StatusBoard StatusBoard::for_stderr() {
  bool terminal = isatty(STDERR_FILENO) != 0;
  winsize size{};
  size_t columns = 0;
  if (terminal && ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0) columns = size.ws_col;
  return StatusBoard(stderr, terminal, columns);
}

void StatusBoard::show(Nanos t, const std::vector<PortStatus>& ports) {
  std::string text = status_lines(ports, t);
  if (!terminal_) {
    std::fprintf(out_, "status at %s:\n%s", duration_literal(t).c_str(), text.c_str());
    std::fflush(out_);
    return;
  }
  std::string frame;
  if (drawn_ > 0) frame += "\x1b[" + std::to_string(drawn_) + "F";  // to the first line drawn
  size_t lines = 0;
  for (size_t at = 0; at < text.size();) {
    size_t end = text.find('\n', at);
    std::string line = text.substr(at, end - at);
    // One screen line each, or the cursor's way back up would miss (a wrapped line is two).
    if (columns_ > 1 && line.size() >= columns_) line = line.substr(0, columns_ - 2) + "~";
    frame += "\x1b[2K" + line + "\n";  // the old line cleared first
    ++lines;
    at = end + 1;
  }
  for (size_t i = lines; i < drawn_; ++i) frame += "\x1b[2K\n";  // fewer lines than last time
  drawn_ = std::max(lines, drawn_);
  std::fputs(frame.c_str(), out_);
  std::fflush(out_);
}

void StatusBoard::attach(RunOptions& options) {
  options.on_status = [this](Nanos t, const std::vector<PortStatus>& ports) { show(t, ports); };
}

}  // namespace arbc::cli
