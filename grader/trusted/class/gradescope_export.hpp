/// @file gradescope_export.hpp
/// A Gradescope export as it comes ("Export Submissions"): one folder per submission,
/// submission_<id>/, and submission_metadata.yml keyed by those folders' names, each entry's
/// :submitters: a list of the group's members with :name:, :sid:, :email: (Ruby symbols written
/// as YAML). Read with yaml-cpp, for scripts/regrade (hw2-export) and the class page (hw2-class):
/// each member of a submission gets a row of its own, with the submission's grade.
/// The file is the instructor's, the names in it the students' own typing: a malformed file is
/// an ExportError naming the file and the line, and every name is kept to one printable line.
/// Each entry's :results: is the results.json Gradescope stored for it (its autograder's, which
/// ran beside the student's code): read_stored_results() gives it as JSON, for hw2-class on an
/// export not regraded, within bounds (kLargestStoredValues ...) that cost its own row alone.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace opspace::grading {

/// The file that marks a folder as a Gradescope export.
inline constexpr const char* kExportMetadata = "submission_metadata.yml";
/// The largest metadata file read (bytes): an export's holds each submission's results.json
/// (at most 1 MB each on Gradescope), so a class of several hundred fits.
inline constexpr std::uintmax_t kLargestMetadata = std::uintmax_t{1} << 30;
/// The most members one submission may name (Gradescope's groups are far smaller).
inline constexpr std::size_t kLargestGroup = 100;
/// The longest name, SID or e-mail kept (bytes); a longer one is cut, at a character's start.
inline constexpr std::size_t kLongestField = 200;

struct Submitter {
  std::string name, sid, email;
};

struct ExportSubmission {
  std::string folder;                 ///< submission_<id>: a plain name (letters, digits, _ . -)
  std::vector<Submitter> submitters;  ///< empty when the entry names nobody
};

/// The most values (YAML nodes, each alias's every repetition counted) one submission's stored
/// results may hold: the grader's results.json holds some thousands (a run's series is one text),
/// and an alias repeated inside an alias ("billion laughs") would otherwise be walked without end.
inline constexpr std::size_t kLargestStoredValues = std::size_t{1} << 20;
/// The deepest nesting of stored results taken: the grader's results.json nests 5 deep.
inline constexpr std::size_t kDeepestStoredResults = 32;
/// The most text (bytes) of one submission's stored results: as a results.json file read by the
/// class page (class_results.hpp's kLargestResults, 16 MiB).
inline constexpr std::uintmax_t kLargestStoredText = std::uintmax_t{16} << 20;

/// A submission as the export stored its grade.
struct StoredSubmission {
  ExportSubmission submission;
  std::string status;  ///< :status: ("processed" when its autograder ran), one printable line
  /// :score:, Gradescope's (manual adjustments and late penalties in); NaN when absent or no number.
  double score = std::numeric_limits<double>::quiet_NaN();
  bool has_results = false;  ///< :results: is there, taken or not
  nlohmann::json results;    ///< :results: as JSON: a plain scalar that reads as a number is a
                             ///< double (.inf and 1e999 kept infinite, for the page to refuse)
  std::string refused;       ///< why :results: was not taken ("" when it was, or is absent)
};

/// "FILE:LINE: what is wrong" (LINE from 1), or "FILE: what is wrong".
struct ExportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Whether `folder` holds submission_metadata.yml.
bool is_gradescope_export(const std::string& folder);

/// The submissions of the metadata file `path`, in the byte order of their folders' names.
/// Throws ExportError when the file cannot be read, is not YAML, or is not an export's metadata.
std::vector<ExportSubmission> read_export_metadata(const std::string& path);

/// Every submission of the metadata file `path` with what Gradescope stored of its grade, in the
/// byte order of their folders' names. Throws ExportError as read_export_metadata does; stored
/// results beyond the bounds above are refused in their entry's `refused`, never the file.
std::vector<StoredSubmission> read_stored_results(const std::string& path);

/// How a member is shown on the class page: "name (SID sid, email)", the parts they have.
std::string submitter_label(const Submitter& s);

/// A CSV field as deploy/scores.cmake writes the gradebook's: a field a spreadsheet would read as
/// a formula behind a ', line breaks written \r \n, quoted (quotes doubled) when it holds , " ; ' a
/// space or a tab.
std::string gradebook_field(std::string text);

}  // namespace opspace::grading
