// SPDX-License-Identifier: GPL-3.0-or-later
#include "frontend/reconstruction_request.hpp"

#include "io/io_error.hpp"

namespace sculpt::frontend {

Reconstruction_outcome run_request(Reconstruction_request request,
                                   const std::function<bool(const Progress&)>& progress) {
  Reconstruction_outcome outcome;
  try {
    Input input;
    if (request.edited_points) {
      input.points = *request.edited_points;
      input.description = std::to_string(request.edited_points->size()) +
                          " samples: " + request.edited_from + ", " +
                          std::to_string(request.edits) + (request.edits == 1 ? " edit" : " edits");
    } else {
      input =
          load_input(request.path, request.example, request.dimension, request.merge_duplicates);
    }
    outcome.description = input.description;
    if (!request.shown_as.empty() && input.description.rfind(request.path, 0) == 0) {
      outcome.description = request.shown_as + input.description.substr(request.path.size());
    }
    request.options.keep_triangulations = true;
    request.options.progress = progress;
    outcome.reconstruction = reconstruct_input(input, request.options);
  } catch (const Cancelled&) {
    outcome.error = "cancelled";
  } catch (const Duplicate_points& e) {
    // The command line's words, with the viewer's way out instead of its flag.
    outcome.error = std::string(e.what()) +
                    " (Reconstruction options > merge repeated points removes repeated points)";
  } catch (const std::exception& e) {
    outcome.error = e.what();
  }
  return outcome;
}

nlohmann::json to_json(const Reconstruction_request& request) {
  const Options& o = request.options;
  nlohmann::json json = {{"path", request.path},
                         {"example", request.example},
                         {"edited_from", request.edited_from},
                         {"edits", request.edits},
                         {"dimension", request.dimension},
                         {"merge_duplicates", request.merge_duplicates},
                         {"shown_as", request.shown_as},
                         {"method", to_string(o.method)},
                         {"kind", to_string(o.kind)},
                         {"rule", to_string(o.rule)},
                         {"box_factor", o.box_factor},
                         {"alpha", o.alpha},
                         {"bordered_seed_sample", o.bordered_seed_sample},
                         {"carve_by_flood", o.carve_by_flood},
                         {"cleaning", to_string(o.cleaning)}};
  if (request.edited_points) {
    nlohmann::json points = nlohmann::json::array();
    for (const Point<2>& p : *request.edited_points) points.push_back({p[0], p[1]});
    json["edited_points"] = std::move(points);
  }
  return json;
}

Reconstruction_request request_from_json(const nlohmann::json& json) {
  Reconstruction_request request;
  try {
    request.path = json.at("path").get<std::string>();
    request.example = json.at("example").get<std::string>();
    request.edited_from = json.at("edited_from").get<std::string>();
    request.edits = json.at("edits").get<int>();
    request.dimension = json.at("dimension").get<int>();
    request.merge_duplicates = json.at("merge_duplicates").get<bool>();
    request.shown_as = json.at("shown_as").get<std::string>();
    Options& o = request.options;
    if (!parse_method(json.at("method").get<std::string>(), o.method) ||
        !parse_kind(json.at("kind").get<std::string>(), o.kind) ||
        !parse_rule(json.at("rule").get<std::string>(), o.rule) ||
        !parse_cleaning(json.at("cleaning").get<std::string>(), o.cleaning))
      throw io::Error("a reconstruction request names an unknown method, kind, rule or cleaning");
    o.box_factor = json.at("box_factor").get<double>();
    o.alpha = json.at("alpha").get<double>();
    o.bordered_seed_sample = json.at("bordered_seed_sample").get<int>();
    o.carve_by_flood = json.at("carve_by_flood").get<bool>();
    if (json.contains("edited_points")) {
      auto points = std::make_shared<std::vector<Point<2>>>();
      for (const auto& p : json.at("edited_points")) points->push_back({p.at(0), p.at(1)});
      request.edited_points = std::move(points);
    }
  } catch (const nlohmann::json::exception& e) {
    throw io::Error(std::string("a reconstruction request is malformed: ") + e.what());
  }
  return request;
}

}  // namespace sculpt::frontend
