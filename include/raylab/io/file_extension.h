#pragma once
/// \file
/// File name extensions, as loaders and writers compare them.

#include <string>
#include <string_view>

namespace raylab {

/// The extension of the last path component, with its dot, in lower case (".png" for
/// "out/Image.PNG"); empty when the file name has no dot.
std::string lowercase_extension(std::string_view path);

}  // namespace raylab
