// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/reconstruction_bytes.hpp"

#include <cstring>
#include <string>
#include <type_traits>

#include "io/io_error.hpp"

namespace sculpt::io {

namespace {

// "SCRB" and a version: bytes of another layout are refused, not misread.
constexpr std::uint32_t magic = 0x42524353;
constexpr std::uint32_t format_version = 5;  // 2: the front and alpha stages; 3: openings, refused
                                             // handles; 4: short loops; 5: outliers removed

class Byte_writer {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  template <class T>
  void values(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    value(std::uint64_t(v.size()));
    if (v.empty()) return;  // data() may be null
    const auto* p = reinterpret_cast<const std::uint8_t*>(v.data());
    bytes_.insert(bytes_.end(), p, p + v.size() * sizeof(T));
  }
  void text(const std::string& s) {
    value(std::uint64_t(s.size()));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
};

class Byte_reader {
 public:
  Byte_reader(const std::uint8_t* bytes, std::size_t size) : at_(bytes), end_(bytes + size) {}

  template <class T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    std::memcpy(&v, take(sizeof(T)), sizeof(T));
    return v;
  }
  template <class T>
  void value(T& v) {
    v = value<T>();
  }
  template <class T>
  void values(std::vector<T>& v) {
    const auto count = value<std::uint64_t>();
    if (count > std::uint64_t(end_ - at_) / sizeof(T)) cut_short();
    v.resize(count);
    const std::uint8_t* source = take(count * sizeof(T));
    if (count > 0) std::memcpy(v.data(), source, count * sizeof(T));  // data() may be null
  }
  void text(std::string& s) {
    const auto count = value<std::uint64_t>();
    if (count > std::uint64_t(end_ - at_)) cut_short();
    s.assign(reinterpret_cast<const char*>(take(count)), count);
  }
  bool at_end() const { return at_ == end_; }

 private:
  const std::uint8_t* take(std::size_t size) {
    if (size > std::size_t(end_ - at_)) cut_short();
    const std::uint8_t* here = at_;
    at_ += size;
    return here;
  }
  [[noreturn]] static void cut_short() {
    throw Error("a reconstruction's bytes are cut short or damaged");
  }
  const std::uint8_t* at_;
  const std::uint8_t* end_;
};

// A field added to these structures must be added to the lists below: their sizes on the two
// machines the project builds for (x86-64, WebAssembly) are checked, so that the compiler says so.
constexpr bool wasm32 = sizeof(void*) == 4;
static_assert(sizeof(Statistics) == (wasm32 ? 288 : 480),
              "a statistic to carry: statistics_fields");
// Written raw: no padding whose bytes would be undefined.
static_assert(std::has_unique_object_representations_v<Carving_opening>);
static_assert(sizeof(Options) == (wasm32 ? 72 : 80), "an option to carry: options_fields");
static_assert(sizeof(Reconstruction<3>) == (wasm32 ? 808 : 1448), "a stage to carry: stage_fields");

// One list of every field, read or written by the same code: a field cannot be written and then
// forgotten when read. `io` is a Byte_writer (fields const) or a Byte_reader.
template <class Io, class Options_ref>
void options_fields(Io& io, Options_ref& o) {
  io.value(o.method);
  io.value(o.kind);
  io.value(o.rule);
  io.value(o.box_factor);
  io.value(o.alpha);
  io.value(o.bordered_seed_sample);
  io.value(o.keep_triangulations);
  io.value(o.keep_solid);
  io.value(o.carve_by_flood);
  io.value(o.cleaning);
}

template <class Io, class Statistics_ref>
void statistics_fields(Io& io, Statistics_ref& s) {
  io.value(s.method);
  io.value(s.kind);
  io.value(s.kind_chosen_automatically);
  io.value(s.closed_spanning_facets);
  io.value(s.dimension);
  io.value(s.samples);
  io.value(s.noise);
  io.value(s.cleaned);
  io.value(s.smoothed);
  io.value(s.outliers_sought);
  io.value(s.outliers_removed);
  io.value(s.noise_after);
  io.value(s.cleaning_shift);
  io.value(s.translation);
  io.value(s.scale_exponent);
  io.value(s.poles);
  io.value(s.convex_poles);
  io.value(s.inner_poles);
  io.value(s.outer_poles);
  io.value(s.unlabelled_poles);
  io.value(s.conflicts);
  io.value(s.conflict_offers);
  io.value(s.carved_cells);
  io.value(s.kept_outer_cells);
  io.value(s.carved_handles);
  io.value(s.refused_handles);
  io.value(s.carved_by_flood);
  io.value(s.inserted_poles);
  io.value(s.delaunay_cells);
  io.value(s.sculpted_cells);
  io.value(s.solid_cells);
  io.value(s.candidate_facets);
  io.value(s.spanning_facets);
  io.value(s.filled_gaps);
  io.value(s.torn_loops);
  io.value(s.short_loops);
  io.value(s.set_in_samples);
  io.value(s.attached_samples);
  io.value(s.closed_notches);
  io.value(s.joined_pinches);
  io.value(s.dropped_fans);
  io.value(s.pruned_facets);
  io.value(s.rims_kept);
  io.value(s.undersampled_samples);
  io.value(s.samples_without_umbrella);
  io.value(s.alpha);
  io.value(s.surface_vertices);
  io.value(s.unbounded_power_faces);
  io.value(s.facets);
  io.value(s.boundary_ridges);
  io.value(s.non_manifold_ridges);
  io.value(s.non_manifold_vertices);
  io.value(s.boundary_loops);
  io.value(s.components);
  io.value(s.euler_characteristic);
  io.value(s.unused_samples);
  io.value(s.thin_handles);
  io.value(s.total_seconds);
}

template <class Io, class Reconstruction_ref>
void stage_fields(Io& io, Reconstruction_ref& r) {
  io.values(r.sites);
  io.value(r.delaunay.cell_count);
  io.values(r.delaunay.cells);
  io.values(r.poles.poles);
  io.values(r.poles.positive_pole);
  io.values(r.poles.negative_pole);
  io.values(r.poles.partner_offsets);
  io.values(r.poles.partners);
  io.values(r.seeds.convex_poles);
  io.values(r.seeds.outer_seeds);
  io.values(r.propagation.events);
  io.values(r.propagation.conflicts);
  io.values(r.propagation.labels);
  io.value(r.propagation.unlabelled);
  io.values(r.insertion.inserted_poles);
  io.value(r.sculpted_delaunay.cell_count);
  io.values(r.sculpted_delaunay.cells);
  io.values(r.carving.events);
  io.values(r.carving.kept_outer_cells);
  io.values(r.carving.buried_samples);
  io.values(r.carving.openings);
  io.values(r.carving.refused_handles);
  io.values(r.crust.voronoi_vertices);
  io.value(r.crust.delaunay.cell_count);
  io.values(r.crust.delaunay.cells);
  io.values(r.candidates.chosen);
  io.values(r.candidates.spanning);
  io.values(r.candidates.pruned);
  io.value(r.candidates.rims_kept);
  io.values(r.candidates.undersampled);
  io.values(r.candidates.without_umbrella);
  io.values(r.front.order);
  io.values(r.alpha.cells);
  io.values(r.alpha.radii);
  io.value(r.alpha.chosen);
  io.values(r.solid);
  io.values(r.surface);
  io.values(r.thin_handles);
  io.values(r.surface_vertices);
  io.values(r.given_samples);
  io.values(r.removed_outliers);
}

}  // namespace

template <int D>
std::vector<std::uint8_t> to_bytes(const Reconstruction<D>& r) {
  Byte_writer out;
  out.value(magic);
  out.value(format_version);
  out.value(std::int32_t(D));
  options_fields(out, r.options);
  stage_fields(out, r);
  statistics_fields(out, r.stats);
  out.value(std::uint64_t(r.stats.stages.size()));
  for (const Stage_measure& stage : r.stats.stages) {
    out.text(stage.name);
    out.value(stage.seconds);
    out.value(stage.peak_memory_mib);
  }
  return out.take();
}

int dimension_of_bytes(const std::uint8_t* bytes, std::size_t size) {
  if (size < 12) return 0;
  Byte_reader in(bytes, size);
  if (in.value<std::uint32_t>() != magic || in.value<std::uint32_t>() != format_version) return 0;
  const auto dimension = in.value<std::int32_t>();
  return dimension == 2 || dimension == 3 ? dimension : 0;
}

template <int D>
Reconstruction<D> reconstruction_from_bytes(const std::uint8_t* bytes, std::size_t size) {
  if (dimension_of_bytes(bytes, size) != D)
    throw Error("these bytes are not a " + std::to_string(D) + "D reconstruction");
  Byte_reader in(bytes, size);
  in.value<std::uint32_t>();
  in.value<std::uint32_t>();
  in.value<std::int32_t>();
  Reconstruction<D> r;
  options_fields(in, r.options);
  stage_fields(in, r);
  statistics_fields(in, r.stats);
  const auto stages = in.value<std::uint64_t>();
  for (std::uint64_t i = 0; i < stages; ++i) {
    Stage_measure stage;
    in.text(stage.name);
    in.value(stage.seconds);
    in.value(stage.peak_memory_mib);
    r.stats.stages.push_back(std::move(stage));
  }
  if (!in.at_end()) throw Error("a reconstruction's bytes go on past its end");
  return r;
}

template std::vector<std::uint8_t> to_bytes(const Reconstruction<2>&);
template std::vector<std::uint8_t> to_bytes(const Reconstruction<3>&);
template Reconstruction<2> reconstruction_from_bytes<2>(const std::uint8_t*, std::size_t);
template Reconstruction<3> reconstruction_from_bytes<3>(const std::uint8_t*, std::size_t);

}  // namespace sculpt::io
