// hw2-class: the class page from a folder of results.json files (grader/trusted/class/class_page.hpp).
//   hw2-class FOLDER [--anonymous] [--out DIR]
// FOLDER holds one subfolder per student with its results.json (scripts/regrade's OUT, or a
// Gradescope export unzipped), or the students' results files themselves (NAME.json). Writes
// DIR/class.html and DIR/mistakes.csv (DIR: FOLDER by default), each whole or not at all. A FOLDER
// that cannot be read or holds no results writes nothing: it says so on stderr and exits 1. A
// FOLDER holding submission_metadata.yml (a Gradescope export; scripts/regrade copies it into OUT)
// names each submission by its members, each a row of their own with the submission's grade
// (gradescope_export.hpp); a metadata file that cannot be read stops the page, with its line. An
// export as it comes (no results.json in it, not regraded) is drawn from the results Gradescope
// stored in its metadata (:results:), and DIR/gradebook.csv is written from them too, a row per
// member (not with --anonymous); an export that stores none writes nothing (exit 1: regrade it).
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
#include <cmath>
#include <filesystem>

#include "class/gradescope_export.hpp"
#include "protocol/problems.hpp"
#endif

namespace {

int usage(std::ostream& out, int code) {
  out << "usage: hw2-class FOLDER [--anonymous] [--out DIR]\n"
         "  writes DIR/class.html and DIR/mistakes.csv (DIR: FOLDER by default) from the results.json of\n"
         "  each student folder of FOLDER; --anonymous numbers the students and names none. On a Gradescope\n"
         "  export not regraded, from the results it stored, and DIR/gradebook.csv too (not with --anonymous)\n";
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

#ifdef OPSPACE_GRADESCOPE_EXPORT
namespace g = opspace::grading;

// A score as the gradebook writes it (deploy/scores.cmake): thousandths at most, no trailing zeros.
std::string points_text(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f", v);
  std::string out = text;
  while (out.back() == '0') out.pop_back();
  if (out.back() == '.') out.pop_back();
  return out == "-0" ? "0" : out;
}

// A Gradescope export as it comes, drawn from the results Gradescope stored (:results:): its
// students (a row per member), the gradebook's first four fields of each (name,sid,email,
// submission) and what the page says of its source.
struct StoredClass {
  std::vector<g::ClassStudent> students;
  std::vector<std::string> leads;
  std::string source;
};

StoredClass stored_class(const std::string& folder) {
  const std::vector<g::StoredSubmission> stored = g::read_stored_results(folder + "/" + g::kExportMetadata);
  if (std::none_of(stored.begin(), stored.end(), [](const g::StoredSubmission& e) { return e.has_results; }))
    throw std::runtime_error("no results in " + folder + ": a Gradescope export whose submission_metadata.yml stores no results "
                             "(:results:) is graded first: scripts/regrade EXPORT OUT");
  StoredClass out;
  std::size_t recorded = 0;
  const auto add = [&](g::ClassStudent s, const std::string& submission, const std::vector<g::Submitter>& members) {
    if (members.empty()) out.leads.push_back(g::gradebook_field(submission) + ",,," + submission);
    for (const g::Submitter& m : members)
      out.leads.push_back(g::gradebook_field(m.name) + "," + g::gradebook_field(m.sid) + "," + g::gradebook_field(m.email) + "," +
                          submission);
    for (std::size_t k = 0; k < std::max<std::size_t>(members.size(), 1); ++k) {
      out.students.push_back(s);
      if (!members.empty()) out.students.back().name = g::submitter_label(members[k]);
    }
  };
  for (const g::StoredSubmission& e : stored) {
    const std::string& name = e.submission.folder;
    g::ClassStudent s;
    s.name = name;
    if (e.has_results && e.refused.empty()) {
      s = g::read_student(name, e.results);
      const nlohmann::json* tests = e.results.is_object() && e.results.contains("tests") ? &e.results["tests"] : nullptr;
      if (tests && tests->is_array() && std::any_of(tests->begin(), tests->end(), [](const nlohmann::json& t) {
            return t.is_object() && t.contains("extra_data") && t["extra_data"].is_object() && t["extra_data"].contains("problem");
          }))
        ++recorded;
    } else {
      s.not_graded = e.has_results ? e.refused : "Gradescope stored no results for it";
    }
    if (!e.status.empty() && e.status != "processed") s.notes.push_back("Gradescope's status for it: " + e.status);
    if (!std::isnan(e.score) && s.not_graded.empty() && !(std::abs(e.score - s.score) <= 1e-6))
      s.notes.push_back("Gradescope's score " + points_text(e.score) + " is not its stored results' " + points_text(s.score) +
                        " (adjusted by hand, or a late penalty?): the page counts the results'");
    add(std::move(s), name, e.submission.submitters);
  }
  // A folder the metadata does not list has no stored results: its row says so.
  std::error_code ec;
  for (const std::filesystem::directory_entry& d : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = d.path().filename().string();
    std::error_code entry;
    if (name.empty() || name[0] == '.' || !d.is_directory(entry) || name.find_first_of("\t\n\r") != std::string::npos) continue;
    if (std::any_of(stored.begin(), stored.end(), [&](const g::StoredSubmission& e) { return e.submission.folder == name; })) continue;
    g::ClassStudent s;
    s.name = name, s.not_graded = "not in submission_metadata.yml: no stored results";
    add(std::move(s), g::gradebook_field(name), {});
  }
  out.source = "Built from the results Gradescope stored in submission_metadata.yml (:results:, what its autograder reported "
               "when each was submitted), not from a regrade; " +
               std::to_string(recorded) + " of " + std::to_string(stored.size()) +
               " submissions' stored results carry each test's record (the mistakes named, the runs plotted): the others' "
               "tests are counted by their names alone, with no run to plot";
  return out;
}

// The gradebook of a Gradescope export drawn from its stored results: the columns scripts/regrade
// writes for an export (name,sid,email,submission, each problem of the list, total, max, note).
void write_gradebook(std::ostream& o, const StoredClass& c) {
  std::vector<std::string> keys;
#define OPSPACE_GRADEBOOK_KEY(key) keys.push_back(#key);
  OPSPACE_PROBLEM_KEYS(OPSPACE_GRADEBOOK_KEY)
#undef OPSPACE_GRADEBOOK_KEY
  o << "name,sid,email,submission";
  for (const std::string& key : keys) o << "," << key;
  o << ",total,max,note\n";
  for (std::size_t i = 0; i < c.students.size(); ++i) {
    const g::ClassStudent& s = c.students[i];
    o << c.leads[i];
    for (const std::string& key : keys) {
      double sum = 0.0;
      bool any = false;
      for (const g::ClassTest& t : s.tests)
        if (t.problem == key) sum += t.score, any = true;
      o << "," << (any ? points_text(sum) : "");
    }
    std::string note = s.not_graded.empty() ? "" : "not graded: " + s.not_graded;
    for (const auto* list : {&s.refused, &s.notes})
      for (const std::string& n : *list) note += (note.empty() ? "" : "; ") + n;
    o << "," << (s.not_graded.empty() ? points_text(s.score) : "") << "," << (s.not_graded.empty() ? points_text(s.max_score) : "")
      << "," << g::gradebook_field(note) << "\n";
  }
}
#endif

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
    std::vector<opspace::grading::ClassStudent> students;
    bool ok = true;
#ifdef OPSPACE_GRADESCOPE_EXPORT
    if (g::is_gradescope_export(folder) && !g::holds_results(folder)) {
      const StoredClass stored = stored_class(folder);
      students = stored.students, options.source = stored.source;
      // Not with --anonymous: the gradebook names everybody, and an anonymous page's folder is for a lecture.
      if (!options.anonymous) ok = write(out_dir + "/gradebook.csv", [&](std::ostream& o) { write_gradebook(o, stored); });
    }
#endif
    if (students.empty()) students = by_member(opspace::grading::read_class(folder), folder);
    ok = ok && write(out_dir + "/class.html", [&](std::ostream& o) { write_class_page(o, students, options); }) &&
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
