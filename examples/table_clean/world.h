// The simulated physical world of the table-cleaning experiment: objects on the table, the
// bucket, the rake's rack, a person, the robot's head and arm. Modules share only this world;
// none of them knows about another (examples/table_clean/README.md#the-world-worldh).
//
// Time is the caller's simulated clock. Scheduled happenings (a person moving an object) sit
// on an agenda that every entry point first advances to `now`, so the world is the same whoever
// looks first. All randomness (detector noise, where a slipped object lands, how long a person
// takes) comes from one generator seeded by the run's seed: same seed and call order, same run.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "examples/table_clean/arm.h"
#include "examples/table_clean/conflicts.h"
#include "examples/table_clean/gaze_referee.h"
#include "examples/table_clean/geometry.h"
#include "examples/table_clean/head.h"
#include "examples/table_clean/person.h"
#include "examples/table_clean/rake.h"
#include "examples/table_clean/rng.h"

namespace arbc::table_clean {

enum class Place { Table, Hand, Bucket };

struct TableObject {
  int id = 0;
  Vec3 pos = Vec3::Zero();
  Place place = Place::Table;
};

// What ObjectDetector reports for one object.
struct Detection {
  Vec3 pos = Vec3::Zero();
  double dist = 0;
};

// What FaceDetector reports while it sees a face.
struct FaceSighting {
  Vec3 pos = Vec3::Zero();
  double certainty = 0;
};

// Scripted uncertainties of the paper (its "perturbed" case).
struct Perturbations {
  bool slip_first_put = false;                  // the first object put slips back onto the table
  bool person_moves_first_rake_target = false;  // while the rake reaches for it
};

class World {
 public:
  // Fixed furniture, in metres, robot at the origin (see geometry.h).
  static Vec3 bucket_position() { return Vec3(0.05, 0.33, 0.05); }
  static Vec3 rake_rack_position() { return Vec3(0.05, -0.33, 0.0); }
  static Vec3 head_position() { return Vec3(0.0, 0.0, 0.35); }

  explicit World(uint64_t seed);

  // --- time -------------------------------------------------------------------------------
  // Runs every agenda entry due at or before `now`, in time order. Time never goes back.
  void advance_to(double now);
  // Schedules `action` at simulated time `at` (runs on the first advance_to(t >= at)).
  void schedule(double at, std::function<void()> action);
  double now() const { return now_; }
  // Called with the due time of every newly scheduled happening, so that a driver with its
  // own clock (the run's environment) can call advance_to exactly then.
  void set_agenda_listener(std::function<void(double at)> listener) {
    agenda_listener_ = std::move(listener);
  }

  // --- objects ----------------------------------------------------------------------------
  int add_object(const Vec3& pos);
  const std::vector<TableObject>& objects() const { return objects_; }
  TableObject& object(int id) { return objects_.at(id); }
  // The object on the table nearest to `pos` within kGraspTolerance, if any.
  std::optional<int> object_on_table_near(const Vec3& pos) const;
  // The object on the table nearest to the robot whose zone is `zone`, if any.
  std::optional<int> nearest_on_table_in(Zone zone) const;
  // A spot in `zone`, clear of zone boundaries and kObjectSpacing from every object on the
  // table (except `ignore`), as close as possible to `azimuth`.
  Vec3 free_spot(Zone zone, double azimuth, int ignore = -1);
  int objects_total() const { return static_cast<int>(objects_.size()); }
  int objects_in_bucket() const;
  bool table_clean() const { return objects_in_bucket() == objects_total(); }
  // Called once, at the instant the last object lands in the bucket.
  void set_on_table_clean(std::function<void()> callback) { on_table_clean_ = std::move(callback); }
  // Records that an object reached the bucket (the arm calls it); fires on_table_clean.
  void object_binned();

  // --- perception -------------------------------------------------------------------------
  // Objects on the table (not held, not in the bucket) with bounded noise; sees the whole
  // table wherever the head looks.
  std::vector<Detection> detect_objects(double now);
  Vec3 detect_bucket(double now);
  // The person's face, only while the head's field of view contains it.
  std::optional<FaceSighting> detect_face(double now);

  // --- actors -----------------------------------------------------------------------------
  Arm& arm() { return arm_; }
  Rake& rake() { return rake_; }
  Head& head() { return head_; }
  Person& person() { return person_; }
  ConflictLog& conflicts() { return conflicts_; }
  const ConflictLog& conflicts() const { return conflicts_; }
  GazeReferee& referee() { return referee_; }
  Perturbations& perturbations() { return perturbations_; }
  Rng& rng() { return rng_; }

 private:
  Rng rng_;
  double now_ = 0;
  std::multimap<double, std::function<void()>> agenda_;
  std::function<void(double)> agenda_listener_;
  std::function<void()> on_table_clean_;
  std::vector<TableObject> objects_;
  Arm arm_;
  Rake rake_;
  Head head_;
  Person person_;
  ConflictLog conflicts_;
  GazeReferee referee_;
  Perturbations perturbations_;
};

// A value uniformly in [-bound, bound].
double uniform_noise(Rng& rng, double bound);
// A value uniformly in [lo, hi].
double uniform(Rng& rng, double lo, double hi);

}  // namespace arbc::table_clean
