#pragma once
/// \file
/// Image textures from PNG and JPEG files (or bytes inside a glTF file), decoded by stb_image,
/// converted from sRGB to linear RGB, and refused before decoding when they are too large.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "raylab/scene/texture_image.h"

namespace raylab {

/// Largest accepted texture width or height, in texels. Real textures stay at or below 16k;
/// anything above is far more likely a corrupt or hostile header than an image worth 3 GiB.
inline constexpr std::uint64_t kMaxTextureSide = 16384;
/// Largest accepted texture area, in texels: 2^28, which is 3 GiB as linear float RGB. With the
/// side limit above it only binds if that limit is ever raised; it is the one that bounds memory.
inline constexpr std::uint64_t kMaxTextureTexels = std::uint64_t{1} << 28;

/// How a texture's stored values relate to the numbers the renderer wants: colour textures
/// (base colour, emission) are sRGB-encoded; data textures (normal, height, metallic-roughness,
/// transmission maps) hold the numbers themselves, as glTF 2.0 prescribes.
enum class TextureEncoding { kSrgb, kLinear };

/// Reads PNG or JPEG file `path` into a linear-RGB texture (8-bit and 16-bit PNG, baseline and
/// progressive JPEG, any channel count: grey is replicated, alpha is dropped). Texel values are
/// taken as sRGB-encoded, as PNG and JPEG colour textures are, and converted to linear, unless
/// `encoding` says they are data (kLinear: a sample s of n bits becomes s / (2^n - 1)). Throws
/// InputError naming the file when it is missing, not a PNG or JPEG image, corrupt, or larger than
/// kMaxTextureSide / kMaxTextureTexels (checked from the header, before anything is decoded).
std::shared_ptr<const TextureImage> load_texture(const std::string& path,
                                                 TextureEncoding encoding = TextureEncoding::kSrgb);

/// As load_texture, for `bytes` already in memory (a glTF data: URI or buffer view). Errors name
/// `file` and start with `element` ("images[2]"), when given.
std::shared_ptr<const TextureImage> decode_texture(std::span<const unsigned char> bytes, const std::string& file,
                                                   const std::string& element = "",
                                                   TextureEncoding encoding = TextureEncoding::kSrgb);

/// 8-bit PNG bytes that load_texture(..., `encoding`) reads back to exactly `image`'s texels, or
/// nothing when some texel is not an 8-bit value of that encoding (those of a 16-bit PNG), which
/// an 8-bit file cannot give back. For writing a scene's textures and maps beside it.
std::optional<std::vector<unsigned char>> encode_texture_png(const TextureImage& image,
                                                             TextureEncoding encoding = TextureEncoding::kSrgb);

}  // namespace raylab
