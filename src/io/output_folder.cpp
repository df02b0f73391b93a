// SPDX-License-Identifier: GPL-3.0-or-later
#include "output_folder.hpp"

#include <filesystem>
#include <system_error>

#include "io_error.hpp"

namespace sculpt::io {

Output_folder::Output_folder(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw Error("an output folder needs a name");
  std::vector<fs::path> missing;  // innermost first
  for (fs::path folder = fs::absolute(path).lexically_normal(); !folder.empty();
       folder = folder.parent_path()) {
    std::error_code error;
    const fs::file_status status = fs::status(folder, error);
    if (fs::exists(status)) {
      if (!fs::is_directory(status)) {
        throw Error("cannot make the folder '" + path + "': '" + folder.string() +
                    "' is not a folder");
      }
      break;
    }
    missing.push_back(folder);
    if (folder == folder.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    std::error_code error;
    const bool made = fs::create_directory(*it, error);
    if (error) {
      remove_created();  // the destructor does not run for a constructor that throws
      throw Error("cannot make the folder '" + path + "': " + error.message());
    }
    if (made) created_.push_back(it->string());  // not one that appeared meanwhile
  }
}

Output_folder::~Output_folder() {
  if (!kept_) remove_created();
}

void Output_folder::remove_created() {
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) {
    std::error_code error;
    std::filesystem::remove(*it, error);  // only if empty: nothing of anyone else's goes
  }
}

}  // namespace sculpt::io
