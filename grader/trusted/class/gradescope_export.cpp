#include "class/gradescope_export.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace opspace::grading {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

// "FILE:LINE: why" for a node (yaml-cpp counts lines from 0).
[[noreturn]] void fail(const std::string& path, const YAML::Mark& mark, const std::string& why) {
  if (mark.is_null()) throw ExportError(path + ": " + why);
  throw ExportError(path + ":" + std::to_string(mark.line + 1) + ": " + why);
}

// The length of the UTF-8 character at text[at], or 0 if the bytes there are not one.
std::size_t utf8_length(const std::string& text, std::size_t at) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(at);
  const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
  if (n == 0 || at + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(at + k) & 0xC0) != 0x80) return 0;
  return n;
}

// A student's typing as one printable line: control characters become spaces and bytes that are
// not UTF-8 become '?' (the page's JSON and the CSV take UTF-8 only); cut at kLongestField.
std::string cleaned(const std::string& text) {
  std::string out;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t n = utf8_length(text, at);
    if (out.size() + std::max<std::size_t>(n, 1) > kLongestField) break;
    if (n == 0) out += '?', ++at;
    else if (n == 1) out += static_cast<unsigned char>(text[at]) < 0x20 || text[at] == 0x7f ? ' ' : text[at], ++at;
    else out.append(text, at, n), at += n;
  }
  const auto first = out.find_first_not_of(' ');
  return first == std::string::npos ? std::string() : out.substr(first, out.find_last_not_of(' ') - first + 1);
}

// A submission's folder name is a path the scripts join to the export's: a plain name only.
bool plain_folder(const std::string& name) {
  if (name.empty() || name == "." || name == ".." || name.size() > 255) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
  });
}

// The value of :key: (Gradescope writes Ruby symbols, ":name"; a plain "name" is taken too).
YAML::Node field(const YAML::Node& map, const std::string& key) {
  for (const auto& entry : map) {
    if (!entry.first.IsScalar()) continue;
    const std::string k = entry.first.Scalar();
    if (k == ":" + key || k == key) return entry.second;
  }
  return YAML::Node();
}

std::string text(const std::string& path, const YAML::Node& node, const std::string& what) {
  if (!node.IsDefined() || node.IsNull()) return "";
  if (!node.IsScalar()) fail(path, node.Mark(), what + " is not a text");
  return cleaned(node.Scalar());
}

}  // namespace

bool is_gradescope_export(const std::string& folder) {
  std::error_code ec;
  return fs::is_regular_file(fs::path(folder) / kExportMetadata, ec);
}

namespace {

// The metadata file's root, read whole (at most kLargestMetadata).
YAML::Node load(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw ExportError(path + ": cannot be read: " + ec.message());
  if (size > kLargestMetadata)
    throw ExportError(path + ": " + std::to_string(size >> 20) + " MiB, beyond the " + std::to_string(kLargestMetadata >> 20) +
                      " MiB read");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  if (!(in && content << in.rdbuf())) throw ExportError(path + ": cannot be read");
  try {
    return YAML::Load(content.str());
  } catch (const YAML::Exception& e) {  // ParserException, and DeepRecursion for a nesting too deep
    fail(path, e.mark, "not YAML: " + e.msg);
  }
}

// Calls each(submission, entry) for every entry of the metadata `root`, in the file's order.
template <class Each>
void each_entry(const std::string& path, const YAML::Node& root, Each each) {
  try {
    if (!root.IsMap()) fail(path, root.Mark(), "not a Gradescope export's metadata: no map of submission folders");
    std::set<std::string> seen;
    for (const auto& entry : root) {
      ExportSubmission s;
      if (!entry.first.IsScalar() || !plain_folder(entry.first.Scalar()))
        fail(path, entry.first.Mark(), "a submission's key is not a plain folder name (letters, digits, _ . -)");
      s.folder = entry.first.Scalar();
      if (!seen.insert(s.folder).second) fail(path, entry.first.Mark(), s.folder + " is listed twice");
      if (!entry.second.IsMap()) fail(path, entry.second.Mark(), s.folder + ": its entry is not a map (:submitters: ...)");
      const YAML::Node members = field(entry.second, "submitters");
      if (members.IsDefined() && !members.IsNull()) {
        if (!members.IsSequence()) fail(path, members.Mark(), s.folder + ": :submitters: is not a list");
        if (members.size() > kLargestGroup)
          fail(path, members.Mark(), s.folder + ": more than " + std::to_string(kLargestGroup) + " submitters");
        for (const YAML::Node& m : members) {
          if (!m.IsMap()) fail(path, m.Mark(), s.folder + ": a submitter is not a map (:name:, :sid:, :email:)");
          s.submitters.push_back({text(path, field(m, "name"), s.folder + ": :name:"), text(path, field(m, "sid"), s.folder + ": :sid:"),
                                  text(path, field(m, "email"), s.folder + ": :email:")});
        }
      }
      each(std::move(s), entry.second);
    }
  } catch (const YAML::Exception& e) {  // a conversion yaml-cpp refused: still the file's fault
    fail(path, e.mark, e.msg);
  }
}

// Why one submission's stored results are not taken.
struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A scalar as JSON. Quoted or tagged, a text; plain, YAML's null, booleans and numbers (Ruby's
// Psych, which writes the export, quotes a text that would read as one), else a text.
Json scalar(const YAML::Node& n) {
  const std::string& v = n.Scalar();
  if (n.Tag() != "?") return v;
  if (v.empty() || v == "~" || v == "null" || v == "Null" || v == "NULL") return nullptr;
  if (v == "true" || v == "True" || v == "TRUE") return true;
  if (v == "false" || v == "False" || v == "FALSE") return false;
  constexpr double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [word, value] : {std::pair<const char*, double>{".inf", inf}, {".Inf", inf}, {".INF", inf}, {"+.inf", inf},
                                    {"-.inf", -inf}, {"-.Inf", -inf}, {"-.INF", -inf}, {".nan", nan}, {".NaN", nan}, {".NAN", nan}})
    if (v == word) return value;
  if (std::string("0123456789+-.").find(v[0]) == std::string::npos) return v;
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);  // 1e999 reads as infinite: the page refuses it
  return end != v.c_str() && *end == '\0' ? Json(d) : Json(v);
}

// What has been walked of one submission's stored results.
struct Budget {
  std::size_t values = 0;
  std::uintmax_t text = 0;
};

void count(Budget& b, std::size_t text) {
  if (++b.values > kLargestStoredValues)
    throw Refused("more than " + std::to_string(kLargestStoredValues) + " values (an alias repeated within an alias?)");
  b.text += text;
  if (b.text > kLargestStoredText) throw Refused("more than " + std::to_string(kLargestStoredText >> 20) + " MiB of text");
}

// `n` as JSON, within the budget. A key written as a Ruby symbol (":tests") is taken as "tests".
Json converted(const YAML::Node& n, std::size_t depth, Budget& b) {
  if (depth > kDeepestStoredResults) throw Refused("nested more than " + std::to_string(kDeepestStoredResults) + " deep");
  count(b, n.IsScalar() ? n.Scalar().size() : 0);
  if (n.IsScalar()) return scalar(n);
  if (n.IsSequence()) {
    Json out = Json::array();
    for (const YAML::Node& e : n) out.push_back(converted(e, depth + 1, b));
    return out;
  }
  if (!n.IsMap()) return nullptr;
  Json out = Json::object();
  for (const auto& e : n) {
    if (!e.first.IsScalar()) throw Refused("a key that is not a text");
    std::string key = e.first.Scalar();
    count(b, key.size());
    if (key.size() > 1 && key[0] == ':') key.erase(0, 1);
    out[key] = converted(e.second, depth + 1, b);
  }
  return out;
}

}  // namespace

std::vector<ExportSubmission> read_export_metadata(const std::string& path) {
  std::vector<ExportSubmission> out;
  each_entry(path, load(path), [&](ExportSubmission s, const YAML::Node&) { out.push_back(std::move(s)); });
  std::sort(out.begin(), out.end(), [](const ExportSubmission& a, const ExportSubmission& b) { return a.folder < b.folder; });
  return out;
}

std::vector<StoredSubmission> read_stored_results(const std::string& path) {
  std::vector<StoredSubmission> out;
  each_entry(path, load(path), [&](ExportSubmission s, const YAML::Node& entry) {
    StoredSubmission stored;
    stored.submission = std::move(s);
    const std::string& folder = stored.submission.folder;
    stored.status = text(path, field(entry, "status"), folder + ": :status:");
    const YAML::Node score = field(entry, "score");
    if (score.IsDefined() && score.IsScalar() && scalar(score).is_number()) stored.score = scalar(score).get<double>();
    const YAML::Node results = field(entry, "results");
    stored.has_results = results.IsDefined() && !results.IsNull();
    if (stored.has_results) {
      try {
        Budget budget;
        stored.results = converted(results, 0, budget);
      } catch (const Refused& e) {
        stored.refused = std::string("its stored results were refused: ") + e.what();
        stored.results = nullptr;
      }
    }
    out.push_back(std::move(stored));
  });
  std::sort(out.begin(), out.end(),
            [](const StoredSubmission& a, const StoredSubmission& b) { return a.submission.folder < b.submission.folder; });
  return out;
}

std::string submitter_label(const Submitter& s) {
  std::string details;
  if (!s.sid.empty()) details = "SID " + s.sid;
  if (!s.email.empty()) details += (details.empty() ? "" : ", ") + s.email;
  const std::string name = s.name.empty() ? "(no name)" : s.name;
  return details.empty() ? name : name + " (" + details + ")";
}

std::string gradebook_field(std::string text) {
  const auto starts_formula = [&] {
    const std::size_t at = text.find_first_not_of(' ');
    if (at == std::string::npos) return false;
    if (std::string("-=+@").find(text[at]) != std::string::npos) return true;
    for (const char* wide : {"\xEF\xBC\x9D", "\xEF\xBC\x8B", "\xEF\xBC\x8D", "\xEF\xBC\xA0"})  // full-width = + - @
      if (text.compare(at, 3, wide) == 0) return true;
    return false;
  };
  if (starts_formula() || (!text.empty() && (text[0] == '\t' || text[0] == '\r'))) text = "'" + text;
  std::string out;
  bool quote = false;
  for (const char c : text) {
    if (c == '\r') out += "\\r";
    else if (c == '\n') out += "\\n";
    else out += c == '"' ? std::string("\"\"") : std::string(1, c);
    quote = quote || std::string("\",; '\t").find(c) != std::string::npos;
  }
  return quote ? "\"" + out + "\"" : out;
}

}  // namespace opspace::grading
