#include "point_reader.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace sculpt::io {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

std::string read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open '" + path + "': " + std::strerror(errno));
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) throw Error("cannot read '" + path + "'");
  return content.str();
}

bool looks_binary(const std::string& content) {
  const auto head = content.substr(0, 4096);
  return std::any_of(head.begin(), head.end(), [](unsigned char c) {
    return c == 0 || (c < 32 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v');
  });
}

// One line of a text point file, split into numbers; a leading `p` or `v` is skipped, and a
// line led by another word is not a point (no numbers).
struct Text_line {
  std::vector<double> numbers;
  bool integer_only = false;  // a single integer: a count header if it comes first
};

Text_line parse_text_line(std::string line, const std::string& where) {
  line = line.substr(0, line.find('#'));
  std::replace(line.begin(), line.end(), ',', ' ');
  std::replace(line.begin(), line.end(), ';', ' ');
  std::istringstream words(line);
  std::string word;
  Text_line parsed;
  bool first = true;
  bool integers = true;
  while (words >> word) {
    const bool leading_word = first && std::isalpha(static_cast<unsigned char>(word[0])) &&
                              word != "nan" && word != "inf" && word != "NaN" && word != "Inf";
    first = false;
    if (leading_word) {
      // `p x y z` (Hoppe's .pts) and `v x y z` (OBJ-like) are points; other records, such as
      // a scanner's `d`, `s` and `g` lines or `vn` normals, are not.
      if (word != "p" && word != "v" && word != "P" && word != "V") return {};
      continue;
    }
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0') {
      throw Error(where + ": '" + word + "' is not a number");
    }
    integers = integers && word.find_first_of(".eE") == std::string::npos;
    parsed.numbers.push_back(value);
  }
  parsed.integer_only = integers && parsed.numbers.size() == 1;
  return parsed;
}

Point_set read_text(const std::string& path, const std::string& content, int forced_dimension) {
  if (looks_binary(content)) {
    throw Error("'" + path + "' is not a text point file (it holds binary data)");
  }
  Point_set set;
  set.dimension = forced_dimension;
  std::istringstream lines(content);
  std::string line;
  long announced = -1;
  int line_number = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    const std::string where = path + ":" + std::to_string(line_number);
    const Text_line parsed = parse_text_line(line, where);
    if (parsed.numbers.empty()) continue;
    if (set.points.empty() && announced < 0 && parsed.integer_only) {
      announced = static_cast<long>(parsed.numbers[0]);
      continue;
    }
    const int columns = static_cast<int>(parsed.numbers.size());
    if (set.dimension == 0) set.dimension = columns >= 3 ? 3 : 2;
    if (columns < set.dimension) {
      throw Error(where + ": expected " + std::to_string(set.dimension) + " coordinates, found " +
                  std::to_string(columns));
    }
    Point<3> p{0, 0, 0};
    for (int k = 0; k < set.dimension; ++k) {
      if (!std::isfinite(parsed.numbers[k])) throw Error(where + ": coordinate is not finite");
      p[k] = parsed.numbers[k];
    }
    set.points.push_back(p);
  }
  if (announced >= 0 && announced != static_cast<long>(set.points.size())) {
    throw Error("'" + path + "' is truncated or malformed: its header announces " +
                std::to_string(announced) + " points, it holds " +
                std::to_string(set.points.size()));
  }
  if (set.dimension == 0) set.dimension = 3;
  return set;
}

template <class Read>
Point_set read_mesh(const std::string& path, const std::string& format, bool binary, Read&& read) {
  std::ifstream in(path, binary ? std::ios::binary : std::ios::in);
  if (!in) throw Error("cannot open '" + path + "': " + std::strerror(errno));
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!read(in, points, polygons)) {
    throw Error("'" + path + "' is not a valid " + format + " file (malformed or truncated)");
  }
  for (const auto& polygon : polygons) {
    for (std::size_t v : polygon) {
      if (v >= points.size()) {
        throw Error("'" + path + "' is not a valid " + format + " file: a face names vertex " +
                    std::to_string(v) + " of " + std::to_string(points.size()));
      }
    }
  }
  Point_set set;
  set.dimension = 3;
  for (const auto& polygon : polygons) {
    for (std::size_t j = 2; j < polygon.size(); ++j) {
      set.triangles.push_back({int(polygon[0]), int(polygon[j - 1]), int(polygon[j])});
    }
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point<3> p{points[i].x(), points[i].y(), points[i].z()};
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      throw Error("'" + path + "': vertex " + std::to_string(i) +
                  " has a coordinate that is not finite");
    }
    set.points.push_back(p);
  }
  return set;
}

}  // namespace

std::string extension_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string extension = path.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

Point_set read_points(const std::string& path) {
  const std::string extension = extension_of(path);
  Point_set set;
  if (extension == ".off") {
    set = read_mesh(path, "OFF", false,
                    [](auto& in, auto& p, auto& f) { return CGAL::IO::read_OFF(in, p, f); });
  } else if (extension == ".obj") {
    set = read_mesh(path, "OBJ", false,
                    [](auto& in, auto& p, auto& f) { return CGAL::IO::read_OBJ(in, p, f); });
  } else if (extension == ".ply") {
    set = read_mesh(path, "PLY", true,
                    [](auto& in, auto& p, auto& f) { return CGAL::IO::read_PLY(in, p, f); });
  } else if (extension == ".stl") {
    set = read_mesh(path, "STL", true,
                    [](auto& in, auto& p, auto& f) { return CGAL::IO::read_STL(in, p, f); });
  } else if (extension == ".xy" || extension == ".p2d") {
    set = read_text(path, read_whole_file(path), 2);
  } else if (extension == ".xyz") {
    set = read_text(path, read_whole_file(path), 3);
  } else if (extension == ".pts" || extension == ".txt" || extension == ".csv" ||
             extension.empty()) {
    set = read_text(path, read_whole_file(path), 0);
  } else {
    throw Error("unknown point format '" + extension + "' of '" + path +
                "' (known: .xyz .pts .txt .csv .xy .p2d .ply .off .obj .stl)");
  }
  if (set.points.empty()) throw Error("'" + path + "' holds no points");
  return set;
}

std::vector<Point<2>> planar_points(const Point_set& set, std::string* dropped) {
  int drop = 2;
  if (set.dimension == 3) {
    std::vector<int> constant;
    for (int k = 0; k < 3; ++k) {
      const bool same = std::all_of(set.points.begin(), set.points.end(),
                                    [&](const Point<3>& p) { return p[k] == set.points[0][k]; });
      if (same) constant.push_back(k);
    }
    if (constant.empty()) {
      throw Error(
          "the points are not in a coordinate plane: no coordinate is the same for all "
          "of them, so they cannot be read as 2D");
    }
    drop = constant.back();
  }
  if (dropped) *dropped = set.dimension == 3 ? std::string(1, "xyz"[drop]) : "";
  std::vector<Point<2>> points;
  points.reserve(set.points.size());
  for (const auto& p : set.points) {
    Point<2> q;
    for (int k = 0, j = 0; k < 3; ++k) {
      if (k != drop) q[j++] = p[k];
    }
    points.push_back(q);
  }
  return points;
}

std::size_t merge_duplicates(Point_set& set) {
  std::vector<std::size_t> order(set.points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return set.points[a] < set.points[b]; });
  std::vector<bool> repeated(set.points.size(), false);
  for (std::size_t k = 1; k < order.size(); ++k) {
    repeated[order[k]] = set.points[order[k]] == set.points[order[k - 1]];
  }
  std::vector<Point<3>> kept;
  kept.reserve(set.points.size());
  std::vector<int> new_index(set.points.size());
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    if (!repeated[i]) {
      new_index[i] = static_cast<int>(kept.size());
      kept.push_back(set.points[i]);
    }
  }
  for (std::size_t k = 1; k < order.size(); ++k) {  // a copy takes its first occurrence's index
    if (repeated[order[k]]) new_index[order[k]] = new_index[order[k - 1]];
  }
  std::vector<std::array<int, 3>> triangles;
  for (auto t : set.triangles) {
    for (int& v : t) v = new_index[v];
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) triangles.push_back(t);
  }
  set.triangles = std::move(triangles);
  const std::size_t merged = set.points.size() - kept.size();
  set.points = std::move(kept);
  return merged;
}

std::vector<Point<3>> spatial_points(const Point_set& set) {
  if (set.dimension == 2) {
    throw Error("the file gives 2 coordinates per point: a surface needs 3 (or use --dim 2)");
  }
  return set.points;
}

}  // namespace sculpt::io
