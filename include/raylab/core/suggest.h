#pragma once
/// \file
/// "Did you mean ...?": the closest valid name to a misspelled one, for error messages that point
/// at the fix (an unknown subcommand, option or structure name).

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace raylab {

/// The number of edits that turn `a` into `b`, each costing 1: insert, delete or replace a
/// character, or swap two neighbouring characters (optimal string alignment). Case-insensitive.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The most edits a word of `length` characters may be from a name for the name to be suggested:
/// 1 up to 4 characters, 2 up to 8, 3 beyond. Short words get few, or anything would match.
std::size_t suggestion_tolerance(std::size_t length);

/// The candidate nearest to `word` when it lies within suggestion_tolerance of `word`'s length;
/// the first of equally near ones. Empty when none is near enough or `word` is a candidate.
std::optional<std::string> closest_name(std::string_view word, std::span<const std::string> candidates);

}  // namespace raylab
