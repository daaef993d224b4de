// hw2-class: the class page from a folder of results.json files (grader/trusted/class_page.hpp).
//   hw2-class FOLDER [--anonymous] [--out DIR]
// FOLDER holds one subfolder per student with its results.json (scripts/regrade's OUT, or a
// Gradescope export unzipped), or the students' results files themselves (NAME.json). Writes
// DIR/class.html and DIR/mistakes.csv (DIR: FOLDER by default), each whole or not at all. A FOLDER
// that cannot be read or holds no results (a Gradescope export not regraded yet) writes nothing:
// it says so on stderr and exits 1.
#include <cstdio>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>

#include "class_page.hpp"

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
    const auto students = opspace::grading::read_class(folder);
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
