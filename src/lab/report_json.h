#pragma once
// Internal to the lab module: the JSON documents of the reports (`raylab compare`, `bench`,
// `quality`), built with nlohmann-json, and how they are written.

#include <nlohmann/json.hpp>

#include <string>

namespace raylab::detail {

/// A report document: keys stay in the order written, which is the order the reports have
/// always had (readers may rely on it when they diff two runs).
using ReportJson = nlohmann::ordered_json;

/// The document as text, indented by two spaces, with a line break at the end. Every
/// floating-point number is written with six significant digits, as fmt's {:.6g} writes it
/// (measurements are not more precise, and it is what the reports have always printed):
/// nlohmann's own dump writes the shortest round-trip digits, which for a value such as
/// 0.00534988 can run to 17. Infinities and NaN are written as null (JSON has neither).
/// Bytes that are not UTF-8 (a scene named by a path in another encoding) are replaced rather
/// than thrown on.
std::string report_text(const ReportJson& doc);

}  // namespace raylab::detail
