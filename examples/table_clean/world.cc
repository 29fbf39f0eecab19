#include "examples/table_clean/world.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace arbc::table_clean {

double uniform_noise(Rng& rng, double bound) { return uniform(rng, -bound, bound); }

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

World::World(uint64_t seed)
    : rng_(seed),
      arm_(*this),
      rake_(*this),
      head_(head_position()),
      person_(*this),
      referee_(conflicts_) {}

void World::advance_to(double now) {
  if (now < now_) return;  // time never goes back; a late caller sees the present
  while (!agenda_.empty() && agenda_.begin()->first <= now) {
    auto node = agenda_.extract(agenda_.begin());
    now_ = std::max(now_, node.key());
    node.mapped()();
  }
  now_ = now;
}

void World::schedule(double at, std::function<void()> action) {
  agenda_.emplace(at, std::move(action));
  if (agenda_listener_) agenda_listener_(at);
}

void World::object_binned() {
  if (table_clean() && on_table_clean_) on_table_clean_();
}

int World::add_object(const Vec3& pos) {
  const int id = static_cast<int>(objects_.size());
  objects_.push_back({id, pos, Place::Table});
  return id;
}

std::optional<int> World::object_on_table_near(const Vec3& pos) const {
  std::optional<int> best;
  double best_d = kGraspTolerance;
  for (const TableObject& obj : objects_) {
    if (obj.place != Place::Table) continue;
    const double d = (obj.pos - pos).norm();
    if (d <= best_d) {
      best_d = d;
      best = obj.id;
    }
  }
  return best;
}

std::optional<int> World::nearest_on_table_in(Zone zone) const {
  std::optional<int> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (const TableObject& obj : objects_) {
    if (obj.place != Place::Table) continue;
    const double d = distance_from_robot(obj.pos);
    if (zone_of(d) == zone && d < best_d) {
      best_d = d;
      best = obj.id;
    }
  }
  return best;
}

Vec3 World::free_spot(Zone zone, double azimuth, int ignore) {
  // The table spans +-1 rad around straight ahead; the bucket and the rack stand beside it.
  constexpr double kMaxAzimuth = 1.0;
  const DistanceRange range = placement_range(zone);
  Vec3 candidate = Vec3::Zero();
  for (int attempt = 0; attempt < 400; ++attempt) {
    const double spread = 0.2 + 0.02 * attempt;  // widen the search as spots prove taken
    const double az = std::clamp(azimuth + uniform_noise(rng_, spread), -kMaxAzimuth, kMaxAzimuth);
    candidate = table_point(uniform(rng_, range.min, range.max), az);
    const bool clear = std::none_of(objects_.begin(), objects_.end(), [&](const TableObject& o) {
      return o.id != ignore && o.place == Place::Table &&
             (o.pos - candidate).norm() < kObjectSpacing;
    });
    if (clear) return candidate;
  }
  return candidate;  // a crowded table: accept a close neighbour rather than fail
}

int World::objects_in_bucket() const {
  return static_cast<int>(std::count_if(objects_.begin(), objects_.end(),
                                        [](const auto& o) { return o.place == Place::Bucket; }));
}

std::vector<Detection> World::detect_objects(double now) {
  advance_to(now);
  std::vector<Detection> out;
  for (const TableObject& obj : objects_) {
    if (obj.place != Place::Table) continue;
    Vec3 seen = obj.pos;
    for (int i = 0; i < 3; ++i) seen[i] += uniform_noise(rng_, kDetectorNoise);
    out.push_back({seen, distance_from_robot(seen)});
  }
  return out;
}

Vec3 World::detect_bucket(double now) {
  advance_to(now);
  Vec3 seen = bucket_position();
  for (int i = 0; i < 3; ++i) seen[i] += uniform_noise(rng_, kDetectorNoise);
  return seen;
}

std::optional<FaceSighting> World::detect_face(double now) {
  advance_to(now);
  if (!person_.present()) return std::nullopt;
  const double angle = angle_between(head_.gaze_direction(now), person_.face() - head_.position());
  if (angle > Head::kFieldOfView) return std::nullopt;
  // Certainty falls off towards the edge of the view but stays above 0.85 while seen.
  FaceSighting sighting;
  sighting.certainty = 0.85 + 0.14 * (1.0 - angle / Head::kFieldOfView);
  sighting.pos = person_.face();
  for (int i = 0; i < 3; ++i) sighting.pos[i] += uniform_noise(rng_, kDetectorNoise);
  return sighting;
}

}  // namespace arbc::table_clean
