// verify_naive APP.json: the naive exclusivity proof (one solver query per pair of rules), the
// baseline that bench/figures/verify.sh measures beside `arbc verify`. Prints the number of
// overlapping pairs and of queries; exit 0 when no pair overlaps, 1 otherwise, 2 on bad input.
#include <cstdio>
#include <fstream>
#include <sstream>

#include "bench/verify/pairwise_baseline.h"
#include "core/app_json.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fputs("usage: verify_naive APP.json\n", stderr);
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  std::string error = "cannot read the file";
  std::optional<arbc::model::App> app;
  if (in) app = arbc::model::from_app_json(text.str(), &error);
  if (!app) {
    std::fprintf(stderr, "verify_naive: %s: %s\n", argv[1], error.c_str());
    return 2;
  }
  arbc::verify::PairwiseResult r = arbc::verify::pairwise_baseline(*app);
  if (!r.ok) {
    std::fprintf(stderr, "verify_naive: %s: malformed model\n", argv[1]);
    return 2;
  }
  std::printf("%lld overlapping pairs, %lld queries\n", r.overlapping_pairs, r.queries);
  return r.overlapping_pairs == 0 ? 0 : 1;
}
