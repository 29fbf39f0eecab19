// The constants a spec compares the parts of a port's messages with, read from the lowered
// model: the bodies of the rules and connections from the port (Connection::body) and the
// predicates of the events derived from it (Event::predicate). `arbc run --stub` draws its
// samples around them (runtime/stand_in_sample.h), so that a stand-in reaches both sides of
// every threshold the spec tests (issue 39: floats in [0, 1) never reached a 45 dB threshold).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/app_model.h"

namespace arbc::model {

// What one part of a message is compared with: numbers (`<`, `<=`, `>`, `>=`, `==`, `!=`
// against a constant) and strings (`==`, `!=`), each sorted and without repeats.
struct ComparedValues {
  std::vector<double> numbers;
  std::vector<std::string> strings;
};

// By part of the message: "" the message itself, "db" a field, "pos.x" a field of a field,
// "objects[].dist" a field of each element of a list ("[].dist" of the message's), "len(objects)"
// a list's length ("len()" the message's). A part
// compared through a `let`, a lambda's parameter (`min_by(objects, o => o.dist)`) or an index
// counts as the part it names; a part inside another computation (`dist(pos, p) < 0.5`) is not
// one (the stand-in draws it as it would otherwise).
using ComparedParts = std::map<std::string, ComparedValues>;

// The parts of the messages of `port` ("Module.port", an out-port) the spec compares with
// constants.
ComparedParts compared_parts(const App& app, const std::string& port);

}  // namespace arbc::model
