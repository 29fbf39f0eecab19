#!/usr/bin/env bash
# Golden tests of `arbc verify` as a whole process: output and exit code per case.
#   golden.sh ARBC [CASE...]                        run the cases (all without CASE arguments)
#   ARBC_UPDATE_GOLDEN=1 golden.sh ARBC [CASE...]   rewrite the expected files (review them by eye)
# Run from the repository root. Each `golden` line below is one case: its name (the expected
# stdout+stderr is tests/verify/golden/NAME), where it runs (`repo`: the repository root;
# `empty`: a scratch folder; `specs`: a scratch folder whose specs/ holds the take mutant, as a
# pre-commit hook sees a repository), the expected exit code, and the arguments of `arbc verify`.
# ctest runs each case as its own test, verify_golden.NAME: tests/verify/CMakeLists.txt reads the
# names from the `golden` lines, so a case added here is a test after the next configure.
set -uo pipefail
root=$PWD
arbc=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
shift
selected=("$@")
dir=$root/tests/verify/golden
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/empty" "$scratch/specs/specs"
cp "$root/tests/verify/table_clean_take_mutant.spec" "$scratch/specs/specs/"
failed=0
ran=()

golden() {
  local name=$1 where=$2 want=$3
  shift 3
  if ((${#selected[@]})) && [[ " ${selected[*]} " != *" $name "* ]]; then return; fi
  ran+=("$name")
  local cwd=$root out rc
  [ "$where" = repo ] || cwd=$scratch/$where
  out=$(cd "$cwd" && "$arbc" verify "$@" 2>&1)
  rc=$?
  if [ "$rc" != "$want" ]; then
    echo "FAIL $name: exit $rc, expected $want"; failed=1
  fi
  if [ -n "${ARBC_UPDATE_GOLDEN:-}" ]; then
    printf '%s\n' "$out" > "$dir/$name"
  elif ! diff -u "$dir/$name" <(printf '%s\n' "$out"); then
    echo "FAIL $name: output differs from $dir/$name"; failed=1
  fi
}

golden proved.txt repo 0 tests/verify/table_clean.app.json tests/verify/search_and_track.app.json
golden proved.json repo 0 --format json tests/verify/table_clean.app.json
golden proved.sarif repo 0 --format sarif tests/verify/table_clean.app.json
golden refuted.txt repo 1 tests/verify/table_clean_take_mutant.app.json
golden refuted.json repo 1 --format json tests/verify/table_clean_take_mutant.app.json
golden refuted.sarif repo 1 --format sarif tests/verify/table_clean_take_mutant.app.json
golden warnings.txt repo 0 tests/verify/table_clean_warnings.app.json
golden sized_numbers.txt repo 1 tests/verify/sized_numbers.spec
golden warnings_strict.txt repo 1 --strict tests/verify/table_clean_warnings.app.json
# A rule whose own body sets what its `when` excludes, and a port all of whose rules are dead.
golden dead_self.txt repo 0 tests/verify/dead_self.spec
# A warning of the front end (lapsing-permission) about a spec that is proved: counted in the
# summary and carried into the JSON and SARIF reports, not only printed on stderr.
golden lapsing.txt repo 0 tests/check/lapsing_permission/lapsing_permission.spec
golden lapsing.json repo 0 --format json tests/check/lapsing_permission/lapsing_permission.spec
golden lapsing.sarif repo 0 --format sarif tests/check/lapsing_permission/lapsing_permission.spec
# Bad input: exit 2 and a message on stderr (pinned: stderr is captured with stdout).
golden missing.txt repo 2 tests/verify/no_such_app.json
golden bad_format.txt specs 2 --format xml tests/verify/table_clean.app.json
# A duration between two nanoseconds (ten digits after the point) is refused at its place: the
# runtime counts whole nanoseconds and the proof reads the same integer (docs/app-json.md).
golden ten_digit_duration.txt repo 2 tests/verify/ten_digit_duration.app.json
# Durations a nanosecond apart (0.999999999s, 1.000000001s): violated at whole nanoseconds and
# replayed; with the unrolling's times as reals this ran into the timeout and said unknown.
golden temporal_ns_slow.txt repo 1 --temporal-bound 6 tests/verify/temporal_ns_slow.spec
# Derived events of one source are decided by one message (issue 38 item 7): two that no value
# makes both true are never both present, and a counterexample sets them only by messages.
golden temporal_feed_exclusive.txt repo 0 tests/verify/temporal_feed_exclusive.spec
golden temporal_feed_lasting.txt repo 1 tests/verify/temporal_feed_lasting.spec
# Specs go through the compiler (front end + lowering).
golden spec_proved.txt repo 0 specs/table_clean.spec specs/search_and_track.spec
golden spec_refuted.txt repo 1 tests/verify/table_clean_take_mutant.spec
golden spec_refuted.sarif repo 1 --format sarif tests/verify/table_clean_take_mutant.spec
# Each proof check the fixtures above do not show: unfed, ownership, complete.
golden findings.txt repo 1 tests/verify/findings.spec
# Each port's container holds its own events (docs/design.md#feeds): a resource kept apart by
# an event of one name that only one port's container holds is refuted; a property reading an
# event that only another port's container holds is vacuous (a warning), not proved.
golden resource_name_fact.txt repo 1 tests/verify/resource_name_fact.spec
golden resource_when_opaque.txt repo 1 tests/verify/resource_when_opaque.spec
golden resource_one_order.txt repo 1 tests/verify/resource_one_order.spec
# Kept apart only by a delivery event that some deliveries do not set: refuted by such a delivery.
golden resource_some_deliveries.txt repo 1 tests/verify/resource_some_deliveries.spec
# Lists of any length (issue 38 item 3): a rule that needs five elements, read through `len`
# only, is refuted by a 5-element message (it was "proved" for lists of at most 4); bodies that
# read `len` and constant indexes are proved for every length. A proof that rests on lists of
# at most --list-bound elements (min_by reads every element) says so in its first line and JSON;
# raised, it is refuted.
golden list_bound.txt repo 1 tests/verify/list_bound.spec
golden list_any_length.txt repo 0 tests/verify/list_any_length.spec
golden list_min_by_any_length.txt repo 1 tests/verify/list_min_by_any_length.spec
golden list_bound_index.txt repo 0 tests/verify/list_bound_index.spec
golden list_bound_index.json repo 0 --format json tests/verify/list_bound_index.spec
golden list_bound_index.sarif repo 0 --format sarif tests/verify/list_bound_index.spec
golden list_bound_raised.txt repo 1 --list-bound 6 tests/verify/list_bound_index.spec
golden list_bound_many_scans.txt repo 0 tests/verify/list_bound_many_scans.spec
# A fixed list (T[N]) is encoded whole: refuted by a 6-element message past the bound of 4,
# with no list-bound assumption, and the counterexample replays.
golden list_fixed.txt repo 1 tests/verify/list_fixed.spec
# Properties over time whose free-model counterexample the runtime does not show (issue 38
# item 7, found by tests/drt): decided among the runs a replay makes, never an internal error.
golden temporal_set_for.txt repo 0 tests/verify/temporal_set_for.spec
golden temporal_shared_source.txt repo 0 tests/verify/temporal_shared_source.spec
golden temporal_derived_same_source.txt repo 0 tests/verify/temporal_derived_same_source.spec
golden temporal_every_step.txt repo 1 tests/verify/temporal_every_step.spec
# A vec3 scaled by a value not encoded is opaque, not a crash (tests/drt seed 38 spec 324).
golden vec3_times_opaque.txt repo 1 tests/verify/vec3_times_opaque.spec
golden norm_dist.txt repo 1 tests/verify/norm_dist.spec
golden int64_min_witness.txt repo 1 tests/verify/int64_min_witness.spec
golden vacuous_other_port.txt repo 0 tests/verify/vacuous_other_port.spec
golden vacuous_other_port_strict.txt repo 1 --strict tests/verify/vacuous_other_port.spec
# No time to decide is "unknown", exit 1, never "proved".
golden unknown_timeout.txt repo 1 --timeout 1e-9 tests/verify/overlap.spec
golden unknown_timeout.json repo 1 --timeout 1e-9 --format json tests/verify/overlap.spec
# An event only an invariant or exclusive group mentions: the fix names them too.
golden invariant_only.txt repo 0 tests/verify/invariant_only.spec
# Input with errors never looks clean: verdict "error", the diagnostics, exit 2.
golden bad_input.json repo 2 --format json tests/verify/bad.spec
golden bad_input.sarif repo 2 --format sarif tests/verify/bad.spec tests/verify/no_such_app.json \
  tests/verify/malformed.app.json
golden bad_input_mixed.txt repo 2 tests/verify/overlap.spec tests/verify/bad.spec
# Properties over time: one holds up to the bound, one is violated with a timed trace.
golden temporal.txt repo 1 tests/verify/temporal.spec
golden temporal_bound.txt repo 0 --temporal-bound 2 tests/verify/temporal.spec
golden temporal.json repo 1 --format json tests/verify/temporal.spec
golden temporal.sarif repo 1 --format sarif tests/verify/temporal.spec
# table_clean with its properties over time: ask's spacing (the throttle), take's (under the
# arm's assumed cycle), search after track (the hold), two absences and `only put after take`
# proved, the response bounded; the mutant without ask's throttle is refuted for ask.
golden table_clean_temporal.txt repo 0 specs/table_clean.spec
golden table_clean_ask_mutant.txt repo 1 tests/verify/table_clean_ask_mutant.spec
# With track's hold halved, search is refuted by `never search within 1s after track`.
golden table_clean_hold_mutant.txt repo 1 tests/verify/table_clean_hold_mutant.spec
# Without e_arm_idle in take's `when`, the arm's assumed busy cycle no longer spaces take.
golden table_clean_arm_mutant.txt repo 1 tests/verify/table_clean_arm_mutant.spec
# Its response (search resumes after faces stop) to a bound that covers the mutant's shortest
# violation (11 messages), and the mutant with a window shorter than the hold plus the period.
golden table_clean_temporal_bound14.txt repo 0 --temporal-bound 14 specs/table_clean.spec
golden table_clean_response_mutant.txt repo 1 --temporal-bound 14 tests/verify/table_clean_response_mutant.spec
# Response and stability with rates: holds up to the bound, violated under the rate, violated
# by silence without one; every format.
golden temporal_response.txt repo 1 tests/verify/temporal_response.spec
golden temporal_response.json repo 1 --format json tests/verify/temporal_response.spec
golden temporal_response.sarif repo 1 --format sarif tests/verify/temporal_response.spec
# A response to an event becoming present (a lost link), answered by a rule or by the port.
golden temporal_failsafe.txt repo 1 tests/verify/temporal_failsafe.spec
golden temporal_failsafe.json repo 1 --format json tests/verify/temporal_failsafe.spec
golden temporal_short_bound.txt repo 0 tests/verify/temporal_short_bound.spec
golden temporal_short_bound_strict.txt repo 1 --strict tests/verify/temporal_short_bound.spec
golden temporal_short_bound.sarif repo 0 --format sarif tests/verify/temporal_short_bound.spec
# Absence and precedence: proved at every decision, bounded, violated with replayed traces;
# table_clean's put without e_taken refuted by `only put after take`.
golden temporal_shapes.txt repo 1 tests/verify/temporal_shapes.spec
golden temporal_shapes.json repo 1 --format json tests/verify/temporal_shapes.spec
golden temporal_shapes.sarif repo 1 --format sarif tests/verify/temporal_shapes.spec
# A port's own delivery events, set only by its deliveries: two properties proved by them, and
# a counterexample whose replay gives free "cancel" rather than setting e_busy itself.
golden temporal_own_delivery.txt repo 1 tests/verify/temporal_own_delivery.spec
golden temporal_own_delivery.json repo 1 --format json tests/verify/temporal_own_delivery.spec
golden table_clean_put_mutant.txt repo 1 tests/verify/table_clean_put_mutant.spec
# Under an environment assumption: JSON lists it with the verdict, SARIF prints it in the message.
golden table_clean_put_mutant.json repo 1 --format json tests/verify/table_clean_put_mutant.spec
golden table_clean_put_mutant.sarif repo 1 --format sarif tests/verify/table_clean_put_mutant.spec
# Message data (docs/checks.md#message-data): rules of one source split by their bodies, overlaps shown
# with a message replayed through the Lua monitors; the arm as a resource of two ports, refuted
# by the issue's two mutations with a concrete message.
golden data_exclusive.txt repo 1 tests/verify/data_exclusive.spec
golden data_exclusive.json repo 1 --format json tests/verify/data_exclusive.spec
# String constants are the bytes Lua compares: an escape-like text and a non-ASCII label refuted.
golden data_string_bytes.txt repo 1 tests/verify/data_string_bytes.spec
golden resource_pull_mutant.txt repo 1 tests/verify/table_clean_pull_mutant.spec
golden resource_pull_mutant.json repo 1 --format json tests/verify/table_clean_pull_mutant.spec
golden resource_pull_mutant.sarif repo 1 --format sarif tests/verify/table_clean_pull_mutant.spec
golden resource_take_mutant.txt repo 1 tests/verify/table_clean_take_reach_mutant.spec
# The arm proved: one pair exclusive by data, one by events, each under its own label.
golden resource_proved.json repo 0 --format json specs/table_clean.spec
# Asserts over `emitted`: proved, refuted with a replayed message, not provable (opaque).
golden data_assert.txt repo 1 tests/verify/data_assert.spec
golden data_assert.json repo 1 --format json tests/verify/data_assert.spec
golden data_assert.sarif repo 1 --format sarif tests/verify/data_assert.spec
# An assert over data on a `script` rule: not proved, says why.
golden data_assert_script.txt repo 1 tests/verify/data_assert_script.spec
# An assert refuted only through monitor state (a `var`): printed with that state, not replayed
# on a fresh monitor that lacks it (never an internal error).
golden data_assert_state.txt repo 1 tests/verify/data_assert_state.spec
# A script that sets an event under a computed name: it may set any event of its port, so an
# unset elsewhere proves nothing and the property over time is unknown, not "holds".
golden script_computed_event.txt repo 1 tests/verify/script_computed_event.spec
# A body and its Lua monitor that disagree (an arbc bug, simulated): `internal`, also on stderr.
golden internal_resource.txt repo 1 tests/verify/internal_resource/app.json
golden internal_assert.txt repo 1 tests/verify/internal_assert/app.json
golden internal_exclusive.txt repo 1 tests/verify/internal_exclusive/app.json
# No arguments: specs/*.spec of the current directory (what the pre-commit hook runs).
golden no_args_no_specs.txt empty 2
golden no_args.txt specs 1

for name in "${selected[@]}"; do
  [[ " ${ran[*]} " == *" $name "* ]] || { echo "FAIL: no case named $name"; failed=1; }
done
echo "${#ran[@]} cases run"
exit $failed
