// hw2-class: the class page from a folder of results.json files (grader/trusted/class/class_page.hpp).
//   hw2-class FOLDER [--anonymous] [--out DIR]
// FOLDER holds one subfolder per student with its results.json (scripts/regrade's OUT, or a
// Gradescope export unzipped), or the students' results files themselves (NAME.json). Writes
// DIR/class.html and DIR/mistakes.csv (DIR: FOLDER by default), each whole or not at all. A FOLDER
// that cannot be read or holds no results (a Gradescope export not regraded yet) writes nothing:
// it says so on stderr and exits 1. A FOLDER holding submission_metadata.yml (a Gradescope export;
// scripts/regrade copies it into OUT) names each submission by its members, each a row of their
// own with the submission's grade (gradescope_export.hpp); a metadata file that cannot be read
// stops the page, with its line.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "class/class_page.hpp"
#ifdef OPSPACE_GRADESCOPE_EXPORT
#include "class/gradescope_export.hpp"
#endif

namespace {

int usage(std::ostream& out, int code) {
  out << "usage: hw2-class FOLDER [--anonymous] [--out DIR]\n"
         "  writes DIR/class.html and DIR/mistakes.csv (DIR: FOLDER by default) from the results.json of\n"
         "  each student folder of FOLDER; --anonymous numbers the students and names none\n";
  return code;
}

// Writes `path` through a temporary file and a rename.
bool write(const std::string& path, const std::function<void(std::ostream&)>& body) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    body(out);
    if (!(out << std::flush)) return false;
  }
  return std::rename(temporary.c_str(), path.c_str()) == 0;
}

}  // namespace

// Each submission of a Gradescope export as its members: a group of two is two rows, one grade.
std::vector<opspace::grading::ClassStudent> by_member(std::vector<opspace::grading::ClassStudent> students,
                                                      const std::string& folder) {
#ifdef OPSPACE_GRADESCOPE_EXPORT
  namespace g = opspace::grading;
  if (!g::is_gradescope_export(folder)) return students;
  const std::vector<g::ExportSubmission> roster = g::read_export_metadata(folder + "/" + g::kExportMetadata);
  std::vector<g::ClassStudent> out;
  for (g::ClassStudent& s : students) {
    const auto it = std::find_if(roster.begin(), roster.end(), [&](const g::ExportSubmission& e) { return e.folder == s.name; });
    if (it == roster.end() || it->submitters.empty()) {
      out.push_back(std::move(s));
      continue;
    }
    for (const g::Submitter& m : it->submitters) {
      out.push_back(s);
      out.back().name = g::submitter_label(m);
    }
  }
  return out;
#else
  if (std::ifstream(folder + "/submission_metadata.yml"))
    throw std::runtime_error(folder + " is a Gradescope export, and this hw2-class was built without yaml-cpp to read its "
                             "submission_metadata.yml: install libyaml-cpp-dev and build again");
  return students;
#endif
}

int main(int argc, char** argv) {
  std::string folder, out_dir;
  opspace::grading::ClassPageOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--anonymous") options.anonymous = true;
    else if (a == "--out" && i + 1 < argc) out_dir = argv[++i];
    else if (a == "-h" || a == "--help") return usage(std::cout, 0);
    else if (!a.empty() && a[0] != '-' && folder.empty()) folder = a;
    else return usage(std::cerr, 2);
  }
  if (folder.empty()) return usage(std::cerr, 2);
  if (out_dir.empty()) out_dir = folder;
  try {
    const auto students = by_member(opspace::grading::read_class(folder), folder);
    const bool ok = write(out_dir + "/class.html", [&](std::ostream& o) { write_class_page(o, students, options); }) &&
                    write(out_dir + "/mistakes.csv", [&](std::ostream& o) { write_mistakes_csv(o, students, options); });
    if (!ok) {
      std::cerr << "hw2-class: cannot write into " << out_dir << "\n";
      return 1;
    }
    std::cout << "class page of " << students.size() << " student(s): " << out_dir << "/class.html, " << out_dir
              << "/mistakes.csv\n";
  } catch (const std::exception& e) {
    std::cerr << "hw2-class: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
