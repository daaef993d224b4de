/// @file page_json.hpp
/// The explorer's JSON, written with nlohmann-json: keys in the order written, numbers as the
/// doubles themselves (the shortest text that reads back as the same double).
#pragma once

#include <nlohmann/json.hpp>

namespace opspace::explore {

using Json = nlohmann::ordered_json;

/// A number for the page, or null for an infinity or a NaN, which JSON cannot write (the page
/// reads null as unbounded).
Json json_number(double v);

}  // namespace opspace::explore
