/// @file gradescope_export.hpp
/// A Gradescope export as it comes ("Export Submissions"): one folder per submission,
/// submission_<id>/, and submission_metadata.yml keyed by those folders' names, each entry's
/// :submitters: a list of the group's members with :name:, :sid:, :email: (Ruby symbols written
/// as YAML). Read with yaml-cpp, for scripts/regrade (hw2-export) and the class page (hw2-class):
/// each member of a submission gets a row of its own, with the submission's grade.
/// The file is the instructor's, the names in it the students' own typing: a malformed file is
/// an ExportError naming the file and the line, and every name is kept to one printable line.
#pragma once

#include <cstdint>
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

/// "FILE:LINE: what is wrong" (LINE from 1), or "FILE: what is wrong".
struct ExportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Whether `folder` holds submission_metadata.yml.
bool is_gradescope_export(const std::string& folder);

/// The submissions of the metadata file `path`, in the byte order of their folders' names.
/// Throws ExportError when the file cannot be read, is not YAML, or is not an export's metadata.
std::vector<ExportSubmission> read_export_metadata(const std::string& path);

/// How a member is shown on the class page: "name (SID sid, email)", the parts they have.
std::string submitter_label(const Submitter& s);

/// A CSV field as deploy/scores.cmake writes the gradebook's: a field a spreadsheet would read as
/// a formula behind a ', line breaks written \r \n, quoted (quotes doubled) when it holds , " ; ' a
/// space or a tab.
std::string gradebook_field(std::string text);

}  // namespace opspace::grading
