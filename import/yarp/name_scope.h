// Spec names given within one scope of an imported spec (the modules; the ports of one module;
// the rules into one port), where two YARP names can become one spec name (`a-b` and `a_b` are
// both `a_b`, spec_names.h) and must still be told apart.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>

namespace arbc::yarp {

class NameScope {
 public:
  // A name some YARP name of the scope becomes as it is. Reserve all before giving any: a
  // name told apart never takes a reserved one, so a YARP name whose spec name is unique
  // keeps it whatever the order.
  void reserve(const std::string& name) { reserved_.insert(name); }

  // The spec name for the thing `owner` whose name becomes `base`: `base` when no earlier
  // owner has it, else the first of base_2, base_3, ... that is neither given nor reserved;
  // `*holder` then says which owner has `base`.
  std::string give(const std::string& base, size_t owner, std::optional<size_t>* holder);

 private:
  std::set<std::string> reserved_;
  std::map<std::string, size_t> given_;  // each name given, with its owner
};

}  // namespace arbc::yarp
