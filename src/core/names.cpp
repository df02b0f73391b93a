// SPDX-License-Identifier: GPL-3.0-or-later
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
    case Label_reason::ball_overlap:
      return "ball overlap";
  }
  return "?";
}

const char* to_string(Method method) {
  switch (method) {
    case Method::paper:
      return "paper";
    case Method::robust:
      return "robust";
    case Method::crust:
      return "crust";
    case Method::nn_crust:
      return "nn-crust";
    case Method::cocone:
      return "cocone";
    case Method::advancing_front:
      return "advancing-front";
    case Method::alpha_shape:
      return "alpha-shape";
    case Method::power_crust:
      return "power-crust";
    case Method::tight_cocone:
      return "tight-cocone";
    case Method::boissonnat:
      return "boissonnat";
  }
  return "?";
}

const std::vector<const char*>& method_names() {
  static const std::vector<const char*> names = {
      to_string(Options{}.method),     to_string(Method::paper),
      to_string(Method::crust),        to_string(Method::nn_crust),
      to_string(Method::cocone),       to_string(Method::advancing_front),
      to_string(Method::alpha_shape),  to_string(Method::power_crust),
      to_string(Method::tight_cocone), to_string(Method::boissonnat)};
  return names;
}

const char* describe(Method method) {
  switch (method) {
    case Method::paper:
      return "Kuo & Yau's algorithm, as published";
    case Method::robust:
      return "confidence labelling and manifold carving";
    case Method::crust:
      return "the crust of Amenta, Bern & Kamvysselis";
    case Method::nn_crust:
      return "the nearest-neighbour crust of Dey & Kumar (curves)";
    case Method::cocone:
      return "the co-cone of Amenta, Choi, Dey & Leekha (surfaces)";
    case Method::advancing_front:
      return "CGAL's Advancing Front of Cohen-Steiner & Da (surfaces)";
    case Method::alpha_shape:
      return "CGAL's alpha shapes, the smallest alpha giving one solid (surfaces)";
    case Method::power_crust:
      return "the power crust of Amenta, Choi & Kolluri (not interpolating)";
    case Method::tight_cocone:
      return "the tight co-cone of Dey & Goswami: watertight (surfaces)";
    case Method::boissonnat:
      return "Boissonnat's greedy sculpting of the hull (1984)";
  }
  return "?";
}

bool sculpts(Method method) {
  return method == Method::paper || method == Method::robust;
}

bool interpolates(Method method) {
  return method != Method::power_crust;
}

bool builds_solid(Method method) {
  return sculpts(method) || method == Method::alpha_shape || method == Method::tight_cocone ||
         method == Method::boissonnat;
}

bool reconstructs_in(Method method, int dimension) {
  if (method == Method::nn_crust) return dimension == 2;
  if (method == Method::cocone || method == Method::tight_cocone ||
      method == Method::advancing_front || method == Method::alpha_shape) {
    return dimension == 3;
  }
  return true;
}

bool parse_method(const std::string& name, Method& method) {
  for (Method m : {Method::paper, Method::robust, Method::crust, Method::nn_crust, Method::cocone,
                   Method::advancing_front, Method::alpha_shape, Method::power_crust,
                   Method::tight_cocone, Method::boissonnat}) {
    if (name == to_string(m)) {
      method = m;
      return true;
    }
  }
  return false;
}

const char* to_string(Carve_reason reason) {
  switch (reason) {
    case Carve_reason::outer_pole_inside:
      return "outer pole in its circumball";
    case Carve_reason::outer_power_cell:
      return "in the power cell of an outer ball";
    case Carve_reason::exposes_sample:
      return "exposes a buried sample";
    case Carve_reason::largest_bulge:
      return "its circumsphere bulges farthest out";
  }
  return "?";
}

const char* to_string(Opening_kind kind) {
  switch (kind) {
    case Opening_kind::cavity:
      return "a cavity opened";
    case Opening_kind::group:
      return "a group of outer cells removed whole";
    case Opening_kind::punch:
      return "a web of outer cells punched through";
  }
  return "?";
}

bool parse_rule(const std::string& name, Surface_rule& rule) {
  if (name == "auto" || name == "automatic") {
    rule = Surface_rule::automatic;
  } else if (name == "skin") {
    rule = Surface_rule::skin;
  } else if (name == "extraction") {
    rule = Surface_rule::extraction;
  } else {
    return false;
  }
  return true;
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

const char* to_string(Cleaning cleaning) {
  switch (cleaning) {
    case Cleaning::none:
      return "none";
    case Cleaning::automatic:
      return "auto";
    case Cleaning::jet:
      return "jet";
    case Cleaning::outliers:
      return "outliers";
    case Cleaning::outliers_and_jet:
      return "outliers+jet";
  }
  return "?";
}

const char* cleaning_choices() {
  return "auto, none, outliers, jet, outliers+jet";
}

bool parse_cleaning(const std::string& name, Cleaning& cleaning) {
  for (Cleaning c : {Cleaning::none, Cleaning::automatic, Cleaning::jet, Cleaning::outliers,
                     Cleaning::outliers_and_jet}) {
    if (name == to_string(c)) {
      cleaning = c;
      return true;
    }
  }
  return false;
}

Surface_rule resolved_rule(const Options& options) {
  if (options.rule != Surface_rule::automatic) return options.rule;
  return options.kind == Surface_kind::closed ? Surface_rule::skin : Surface_rule::extraction;
}

bool inserts_poles(Method method, Surface_kind kind, int dimension) {
  return method == Method::paper ||
         (method == Method::robust && kind == Surface_kind::bordered && dimension == 3);
}

bool joins_neighbours(Method method, Surface_kind kind, int dimension) {
  return method == Method::robust && kind == Surface_kind::bordered && dimension == 2;
}

bool parse_kind(const std::string& name, Surface_kind& kind) {
  for (const Surface_kind k :
       {Surface_kind::closed, Surface_kind::bordered, Surface_kind::automatic}) {
    if (name == to_string(k)) {
      kind = k;
      return true;
    }
  }
  return false;
}

bool chooses_kind(Method method) {
  return method == Method::robust;
}

const char* to_string(Surface_kind kind) {
  switch (kind) {
    case Surface_kind::closed:
      return "closed";
    case Surface_kind::bordered:
      return "bordered";
    case Surface_kind::automatic:
      return "automatic";
  }
  return "?";
}

const char* version() {
  return SCULPT_VERSION;
}

}  // namespace sculpt
