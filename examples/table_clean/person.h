// The person across the table. Present or not; while present, their face can be seen, and when
// they hear a request they move the nearest object the robot cannot reach (even with the rake)
// into hand reach after a few seconds, one request at a time.
#pragma once

#include <string>

#include "examples/table_clean/geometry.h"

namespace arbc::table_clean {

class World;

class Person {
 public:
  static constexpr double kMinHelpDelay = 2.0;  // seconds from hearing to the object's move
  static constexpr double kMaxHelpDelay = 4.0;

  explicit Person(World& world) : world_(world) {}

  bool present() const { return present_; }
  void set_present(bool present) { present_ = present; }
  const Vec3& face() const { return face_; }
  void set_face(const Vec3& face) { face_ = face; }

  // Hears `text` at `now`: if present and not already helping, schedules the help.
  void hear(const std::string& text, double now);
  // Moves object `id` from wherever it is on the table to a free spot in hand reach.
  void move_into_hand_reach(int id);

  int requests_heard() const { return requests_heard_; }
  int objects_moved() const { return objects_moved_; }
  bool helping() const { return helping_; }

 private:
  void help();

  World& world_;
  bool present_ = true;
  Vec3 face_ = Vec3(1.0, 0.55, 0.45);
  bool helping_ = false;
  int requests_heard_ = 0;
  int objects_moved_ = 0;
};

}  // namespace arbc::table_clean
