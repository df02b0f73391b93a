// SPDX-License-Identifier: GPL-3.0-or-later
// The compiled part of the Python module `sculpt` (sculpt._sculpt; python/sculpt/__init__.py is
// what users import). It calls the same core as the command line: methods and stages by the same
// names, the same one-line messages for bad input, the same statistics (statistics_json).
// This file defines the module and its exceptions; the bind_* functions (bindings.hpp) add the
// rest, in the order help() shows.
#include <exception>
#include <string>

#include "io/io_error.hpp"
#include "io/temporary_files.hpp"
#include "python/bindings.hpp"

PYBIND11_MODULE(_sculpt, m) {
  using namespace sculpt;
  using namespace sculpt::python;
  m.doc() = "Sculpt's compiled core: see the package sculpt";
  // A write() ended by a signal (SIGTERM, ...) leaves no hidden temporary; Python's own handlers
  // (SIGINT) stay as they are.
  io::remove_temporaries_on_signals();

  // Bad input raises one of these with the line the command line prints after "sculpt: error: ".
  static py::exception<Input_error> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<Duplicate_points> duplicates(m, "DuplicatePoints", input_error.ptr());
  static py::exception<Cancelled> cancelled(m, "Cancelled", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const Duplicate_points& e) {
      duplicates(
          (std::string(e.what()) + " (merge_duplicates=True removes repeated points)").c_str());
    } catch (const Input_error& e) {
      input_error(e.what());
    } catch (const io::Error& e) {
      input_error(e.what());
    } catch (const Cancelled& e) {
      cancelled(e.what());
    }
  });
  input_error.doc() = "Input Sculpt cannot work on: the message is the line `sculpt` prints.";
  duplicates.doc() = "Two points at the same place: merge_duplicates=True drops the copies.";
  cancelled.doc() = "The progress callback returned False.";

  bind_catalogue(m);
  bind_reading(m);
  bind_points(m);
  bind_reconstruction(m);
  bind_rendering(m);
  bind_writing(m);
}
