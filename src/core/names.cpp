// Names of the core's enumerations, as the command line and the statistics print them.
#include <sculpt/sculpt.hpp>

#ifndef SCULPT_VERSION
#define SCULPT_VERSION "0.0.0"
#endif

namespace sculpt {

const char* to_string(Label label) {
  switch (label) {
    case Label::unlabelled:
      return "unlabelled";
    case Label::inner:
      return "inner";
    case Label::outer:
      return "outer";
  }
  return "?";
}

const char* to_string(Label_reason reason) {
  switch (reason) {
    case Label_reason::convex_seed:
      return "convex seed";
    case Label_reason::pairing:
      return "pairing";
    case Label_reason::inscribed_cube:
      return "inscribed cube";
  }
  return "?";
}

const char* to_string(Surface_rule rule) {
  switch (rule) {
    case Surface_rule::automatic:
      return "automatic";
    case Surface_rule::skin:
      return "skin";
    case Surface_rule::extraction:
      return "extraction";
  }
  return "?";
}

Surface_rule resolved_rule(const Options& options) {
  if (options.rule != Surface_rule::automatic) return options.rule;
  return options.kind == Surface_kind::closed ? Surface_rule::skin : Surface_rule::extraction;
}

const char* to_string(Surface_kind kind) {
  return kind == Surface_kind::closed ? "closed" : "bordered";
}

const char* version() {
  return SCULPT_VERSION;
}

}  // namespace sculpt
