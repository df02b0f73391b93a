// SPDX-License-Identifier: GPL-3.0-or-later
// 2D curves: chained into polylines where the curve is a manifold (every sample starts and ends
// at most one edge), one element per edge otherwise.
#include <algorithm>
#include <iomanip>
#include <limits>

#include "atomic_file.hpp"
#include "point_reader.hpp"
#include "writers.hpp"

namespace sculpt::io {

const char* const curve_formats = ".obj .svg";

bool writes_curve(const std::string& extension) {
  return extension == ".obj" || extension == ".svg";
}

namespace {

// Polylines through the oriented edges; closed ones repeat their first sample at the end.
std::vector<std::vector<int>> chain(std::size_t sample_count, const std::vector<Facet<2>>& edges) {
  std::vector<int> next(sample_count, -1), in_degree(sample_count, 0);
  for (const auto& e : edges) {
    if (next[e[0]] >= 0 || in_degree[e[1]] > 0) {
      std::vector<std::vector<int>> single;  // branching: one polyline per edge
      for (const auto& f : edges) single.push_back({f[0], f[1]});
      return single;
    }
    next[e[0]] = e[1];
    ++in_degree[e[1]];
  }
  std::vector<std::vector<int>> lines;
  std::vector<bool> done(sample_count, false);
  const auto walk = [&](int start) {
    std::vector<int> line{start};
    done[start] = true;
    for (int v = next[start]; v >= 0; v = next[v]) {
      line.push_back(v);
      if (done[v]) break;
      done[v] = true;
    }
    lines.push_back(line);
  };
  for (std::size_t v = 0; v < sample_count; ++v) {  // open curves first, from their start
    if (next[v] >= 0 && in_degree[v] == 0) walk(static_cast<int>(v));
  }
  for (std::size_t v = 0; v < sample_count; ++v) {  // then closed loops
    if (next[v] >= 0 && !done[v]) walk(static_cast<int>(v));
  }
  return lines;
}

void write_obj(std::ostream& out, const std::vector<Point<2>>& samples,
               const std::vector<std::vector<int>>& lines) {
  out << "# sculpt curve: " << samples.size() << " samples, " << lines.size() << " polylines\n";
  for (const auto& p : samples) out << "v " << p[0] << ' ' << p[1] << " 0\n";
  for (const auto& line : lines) {
    out << 'l';
    for (int v : line) out << ' ' << v + 1;
    out << '\n';
  }
}

void write_svg(std::ostream& out, const std::vector<Point<2>>& samples,
               const std::vector<std::vector<int>>& lines) {
  double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const auto& p : samples) {
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-300});
  const double margin = 0.05 * size, stroke = 0.004 * size;
  // SVG's y axis points down: flip y so the picture is the right way up.
  const auto x = [&](const Point<2>& p) { return p[0]; };
  const auto y = [&](const Point<2>& p) { return lo[1] + hi[1] - p[1]; };
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << lo[0] - margin << ' '
      << lo[1] - margin << ' ' << hi[0] - lo[0] + 2 * margin << ' ' << hi[1] - lo[1] + 2 * margin
      << "\" width=\"800\" height=\""
      << int(800 * (hi[1] - lo[1] + 2 * margin) / (hi[0] - lo[0] + 2 * margin))
      << "\">\n<g fill=\"none\" stroke=\"black\" stroke-width=\"" << stroke
      << "\" stroke-linejoin=\"round\">\n";
  for (const auto& line : lines) {
    out << "<path d=\"";
    for (std::size_t i = 0; i < line.size(); ++i) {
      out << (i ? " L" : "M") << x(samples[line[i]]) << ',' << y(samples[line[i]]);
    }
    out << "\"/>\n";
  }
  out << "</g>\n<g fill=\"green\">\n";
  for (const auto& p : samples) {
    out << "<circle cx=\"" << x(p) << "\" cy=\"" << y(p) << "\" r=\"" << 1.5 * stroke << "\"/>\n";
  }
  out << "</g>\n</svg>\n";
}

}  // namespace

void write_curve(const std::string& path, const std::vector<Point<2>>& samples,
                 const std::vector<Facet<2>>& edges) {
  const std::string extension = extension_of(path);
  if (!writes_curve(extension)) {
    throw Error("cannot write a curve as '" + extension + "' (known: " + curve_formats + ")");
  }
  const auto lines = chain(samples.size(), edges);
  Atomic_file file(path, false);
  file.stream() << std::setprecision(17);
  if (extension == ".obj") write_obj(file.stream(), samples, lines);
  if (extension == ".svg") write_svg(file.stream(), samples, lines);
  file.commit();
}

}  // namespace sculpt::io
