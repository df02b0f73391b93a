// SPDX-License-Identifier: GPL-3.0-or-later
// Live editing of a 2D point set, the classic way to teach Voronoi, Delaunay, poles and
// undersampling: add a sample, drag one, delete one, draw a stroke of samples, and watch every
// stage change. The editor holds the points and an undo history; the viewer reconstructs them
// after each edit.
#pragma once

#include <optional>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

namespace sculpt::viewer {

class Point_editor {
 public:
  // Starts editing these points (the samples on screen), with an empty history.
  void start(std::vector<Point<2>> points, std::string origin);
  bool active() const { return active_; }
  void stop() { *this = Point_editor{}; }

  const std::vector<Point<2>>& points() const { return points_; }
  // What the points came from ("example star", a file name) and how many edits since.
  const std::string& origin() const { return origin_; }
  int edits() const { return edits_; }

  // Each edit returns false, with a reason in why(), when it cannot be made: a sample already
  // there (the triangulation refuses repeated points) or an index out of range.
  bool add(const Point<2>& p);
  bool add_all(const std::vector<Point<2>>& points);  // one edit: a stroke's samples
  bool move(int sample, const Point<2>& to);
  bool remove(int sample);
  bool undo();
  const std::string& why() const { return why_; }

  // A drag is one edit however many moves it makes: the history keeps the points before it.
  void begin_drag() { dragging_ = false; }
  bool drag(int sample, const Point<2>& to);

  // The sample nearest `p` within `radius`, or -1.
  int nearest(const Point<2>& p, double radius) const;

 private:
  void remember();  // the points before an edit, for undo
  bool index_ok(int sample);

  bool active_ = false;
  std::vector<Point<2>> points_;
  std::vector<std::vector<Point<2>>> history_;
  std::string origin_, why_;
  int edits_ = 0;
  bool dragging_ = false;
};

// Writes points as a .xy file (x y per line, full precision), all or nothing.
void save_points(const std::string& path, const std::vector<Point<2>>& points);

}  // namespace sculpt::viewer
