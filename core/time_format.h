// How instants of one run are written: in the run report (its header, its timelines' hovers,
// the cursor's label and the axis, its log), the line `arbc run` ends with and the runtime's
// reports. A fixed "%.3f s" made every event of a sub-millisecond run read 0.000 or 0.001. The
// unit follows the run's length: s for a run of a second or more, ms below that, µs below a
// millisecond. The decimals follow the finest place a reader can point at (a pixel of the
// report's plot): at least milliseconds in seconds, as before, and more for a short run.
#pragma once

#include <string>

namespace arbc {

class TimeFormat {
 public:
  // `end`: the run's length in seconds; `resolution`: the smallest span worth telling apart.
  TimeFormat(double end, double resolution);
  // For text about a run of `length` seconds that has no plot (the line `arbc run` prints, the
  // runtime's reports): the decimals that tell a thousandth of the run apart, about a pixel of
  // the report's timelines.
  static TimeFormat for_run(double length);

  const char* unit() const { return unit_; }         // "s", "ms", "µs"
  double per_second() const { return per_second_; }  // units in a second
  int decimals() const { return decimals_; }

  std::string number(double seconds) const;  // "12.345" (in the unit, without it)
  std::string text(double seconds) const;    // "12.345 s"
  // "1.2345–1.2347 ms": with more decimals where needed to tell `from` and `to` apart (spans
  // shorter than the resolution), up to nanoseconds.
  std::string span(double from, double to) const;

 private:
  std::string number(double seconds, int decimals) const;
  const char* unit_;
  double per_second_;
  int decimals_;
};

}  // namespace arbc
