// Names of the core's enumerations, as the command line and the statistics print them.
#include <sculpt/sculpt.hpp>

#ifndef SCULPT_VERSION
#define SCULPT_VERSION "0.0.0"
#endif

namespace sculpt {

const char* to_string(Label label) {
  switch (label) {
    case Label::unlabelled: return "unlabelled";
    case Label::inner: return "inner";
    case Label::outer: return "outer";
  }
  return "?";
}

const char* to_string(Label_reason reason) {
  switch (reason) {
    case Label_reason::convex_seed: return "convex seed";
    case Label_reason::pairing: return "pairing";
    case Label_reason::inscribed_cube: return "inscribed cube";
  }
  return "?";
}

const char* to_string(Surface_rule rule) {
  return rule == Surface_rule::skin ? "skin" : "extraction";
}

const char* to_string(Surface_kind kind) {
  return kind == Surface_kind::closed ? "closed" : "bordered";
}

const char* version() { return SCULPT_VERSION; }

}  // namespace sculpt
