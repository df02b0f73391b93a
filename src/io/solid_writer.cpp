// SPDX-License-Identifier: GPL-3.0-or-later
// The sculpted solid as a volume mesh: tetrahedra in 3D, triangles in 2D.
#include <iomanip>

#include "atomic_file.hpp"
#include "point_reader.hpp"
#include "writers.hpp"

namespace sculpt::io {

const char* const solid_formats = ".mesh .vtu .node/.ele";

bool writes_solid(const std::string& extension) {
  return extension == ".mesh" || extension == ".vtu" || extension == ".node" || extension == ".ele";
}

namespace {

template <int D>
void write_medit(std::ostream& out, const std::vector<Point<D>>& samples,
                 const std::vector<Cell<D>>& cells) {
  out << "MeshVersionFormatted 2\nDimension " << D << "\nVertices\n" << samples.size() << '\n';
  for (const auto& p : samples) {
    for (double x : p) out << x << ' ';
    out << "0\n";
  }
  out << (D == 3 ? "Tetrahedra\n" : "Triangles\n") << cells.size() << '\n';
  for (const auto& cell : cells) {
    for (int v : cell) out << v + 1 << ' ';
    out << "1\n";
  }
  out << "End\n";
}

template <int D>
void write_vtu(std::ostream& out, const std::vector<Point<D>>& samples,
               const std::vector<Cell<D>>& cells) {
  const int vtk_type = D == 3 ? 10 : 5;  // VTK_TETRA, VTK_TRIANGLE
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "<UnstructuredGrid>\n<Piece NumberOfPoints=\""
      << samples.size() << "\" NumberOfCells=\"" << cells.size() << "\">\n"
      << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : samples)
    out << p[0] << ' ' << p[1] << ' ' << (D == 3 ? p[D - 1] : 0.0) << '\n';
  out << "</DataArray>\n</Points>\n<Cells>\n"
         "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& cell : cells) {
    for (int v : cell) out << v << ' ';
    out << '\n';
  }
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 1; i <= cells.size(); ++i) out << i * (D + 1) << '\n';
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < cells.size(); ++i) out << vtk_type << '\n';
  out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

template <int D>
void write_tetgen(const std::string& stem, const std::vector<Point<D>>& samples,
                  const std::vector<Cell<D>>& cells) {
  Atomic_file node(stem + ".node", false), ele(stem + ".ele", false);
  node.stream() << std::setprecision(17) << samples.size() << ' ' << D << " 0 0\n";
  for (std::size_t i = 0; i < samples.size(); ++i) {
    node.stream() << i;
    for (double x : samples[i]) node.stream() << ' ' << x;
    node.stream() << '\n';
  }
  ele.stream() << cells.size() << ' ' << D + 1 << " 0\n";
  for (std::size_t i = 0; i < cells.size(); ++i) {
    ele.stream() << i;
    for (int v : cells[i]) ele.stream() << ' ' << v;
    ele.stream() << '\n';
  }
  node.commit();
  ele.commit();
}

}  // namespace

template <int D>
void write_solid(const std::string& path, const std::vector<Point<D>>& samples,
                 const std::vector<Cell<D>>& cells) {
  const std::string extension = extension_of(path);
  if (extension == ".node" || extension == ".ele") {
    write_tetgen<D>(path.substr(0, path.size() - extension.size()), samples, cells);
    return;
  }
  if (!writes_solid(extension)) {
    throw Error("cannot write a solid as '" + extension + "' (known: " + solid_formats + ")");
  }
  Atomic_file file(path, false);
  file.stream() << std::setprecision(17);
  if (extension == ".mesh") write_medit<D>(file.stream(), samples, cells);
  if (extension == ".vtu") write_vtu<D>(file.stream(), samples, cells);
  file.commit();
}

template void write_solid<2>(const std::string&, const std::vector<Point<2>>&,
                             const std::vector<Cell<2>>&);
template void write_solid<3>(const std::string&, const std::vector<Point<3>>&,
                             const std::vector<Cell<3>>&);

}  // namespace sculpt::io
