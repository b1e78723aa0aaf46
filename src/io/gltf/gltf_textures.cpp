#include "gltf_reader.h"

namespace raylab::gltf_detail {

std::shared_ptr<const TextureImage> GltfReader::texture(int index, const std::string& user, TextureEncoding encoding) {
  check_index(index, m_model.textures.size(), user + ".index", "texture");
  const std::string element = "textures[" + std::to_string(index) + "]";
  const tinygltf::Texture& t = m_model.textures[static_cast<std::size_t>(index)];
  if (t.source == -1)
    fail(element, "no PNG or JPEG source (texture extensions such as KHR_texture_basisu are not supported)");
  check_index(t.source, m_model.images.size(), element + ".source", "image");
  if (t.sampler != -1) {
    check_index(t.sampler, m_model.samplers.size(), element + ".sampler", "sampler");
    const tinygltf::Sampler& s = m_model.samplers[static_cast<std::size_t>(t.sampler)];
    if (s.wrapS != TINYGLTF_TEXTURE_WRAP_REPEAT || s.wrapT != TINYGLTF_TEXTURE_WRAP_REPEAT) {
      warn(element + ": clamped or mirrored wrapping is read as repeat");
    }
  }
  std::shared_ptr<const TextureImage>& image = m_images[{t.source, encoding}];
  if (!image) image = decode_image(t.source, encoding);
  return image;
}

std::shared_ptr<const TextureImage> GltfReader::decode_image(int index, TextureEncoding encoding) {
  const std::string element = "images[" + std::to_string(index) + "]";
  const tinygltf::Image& image = m_model.images[static_cast<std::size_t>(index)];
  if (image.bufferView != -1) {
    check_index(image.bufferView, m_model.bufferViews.size(), element + ".bufferView", "bufferView");
    return decode_texture(view_bytes(image.bufferView), m_path, element, encoding);
  }
  const auto it = m_ctx.image_bytes.find(index);
  if (it == m_ctx.image_bytes.end()) fail(element, "cannot read image '" + image.uri + "' (not found)");
  return decode_texture(it->second, m_path, element, encoding);
}

}  // namespace raylab::gltf_detail
