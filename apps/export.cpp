// hw2-export: the rows of a Gradescope export (grader/trusted/class/gradescope_export.hpp), for
// scripts/regrade.
//   hw2-export EXPORT
// Prints one line per member of each submission: FOLDER, a tab, then the member's name, SID and
// e-mail as three gradebook fields (gradebook_field: escaped, no tab or line break). A folder of
// EXPORT that the metadata does not list is one row named after it, without SID or e-mail; one
// it lists with nobody in it too. A metadata file that cannot be read or is not an export's:
// "hw2-export: FILE:LINE: why" on stderr, exit 1.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>

#include "class/gradescope_export.hpp"

namespace fs = std::filesystem;
using namespace opspace::grading;

int main(int argc, char** argv) {
  if (argc != 2 || argv[1][0] == '-') {
    std::cerr << "usage: hw2-export EXPORT\n  lists the rows of a Gradescope export: FOLDER<tab>name,sid,email per member\n";
    return 2;
  }
  const std::string folder = argv[1];
  try {
    std::vector<ExportSubmission> submissions = read_export_metadata((fs::path(folder) / kExportMetadata).string());
    std::error_code ec;
    const std::size_t listed = submissions.size();
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
      const std::string name = e.path().filename().string();
      std::error_code entry;
      if (name.empty() || name[0] == '.' || !e.is_directory(entry)) continue;
      const auto end = submissions.begin() + static_cast<std::ptrdiff_t>(listed);
      if (std::none_of(submissions.begin(), end, [&](const ExportSubmission& s) { return s.folder == name; }))
        submissions.push_back({name, {}});
    }
    if (ec) throw ExportError(folder + ": cannot be read: " + ec.message());
    std::sort(submissions.begin(), submissions.end(), [](const auto& a, const auto& b) { return a.folder < b.folder; });
    for (const ExportSubmission& s : submissions) {
      // A folder the metadata could not have named (a line break in it) is no row: regrade's
      // lines are split on line breaks and tabs.
      if (s.folder.find_first_of("\t\n\r") != std::string::npos) continue;
      if (s.submitters.empty()) std::cout << s.folder << "\t" << gradebook_field(s.folder) << ",,\n";
      for (const Submitter& m : s.submitters)
        std::cout << s.folder << "\t" << gradebook_field(m.name) << "," << gradebook_field(m.sid) << ","
                  << gradebook_field(m.email) << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "hw2-export: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
