#pragma once
/// \file
/// The names of the settings a checkpoint records (image_settings) and a resumed render reads
/// back (fill_from_checkpoint): one spelling for the writer and the reader, so that a renamed
/// setting cannot leave old checkpoints unreadable in one place and not the other.

namespace raylab::setting_name {

inline constexpr char kWidth[] = "width";                 ///< image width in pixels
inline constexpr char kHeight[] = "height";               ///< image height in pixels
inline constexpr char kSpp[] = "spp";                     ///< samples per pixel
inline constexpr char kSampler[] = "sampler";             ///< the sampler, resolved ("auto" never)
inline constexpr char kFilter[] = "filter";               ///< the reconstruction filter
inline constexpr char kFilterRadius[] = "filter radius";  ///< its half-width in pixels
inline constexpr char kSeed[] = "seed";                   ///< seed of every random choice
inline constexpr char kMaxDepth[] = "max depth";          ///< ray tree depth
inline constexpr char kTileSize[] = "tile size";          ///< tile side in pixels
inline constexpr char kPasses[] = "passes";               ///< passes over the image
inline constexpr char kAccel[] = "accel";                 ///< the acceleration structure
/// The integrator, recorded only when it is not "whitted" (so checkpoints written before there
/// was a choice read as Whitted renders, which they were).
inline constexpr char kIntegrator[] = "integrator";
// The environment given over the scene's (--env, --env-rotate), recorded only when given.
inline constexpr char kEnvironment[] = "env";               ///< --env: "R,G,B" or an image file
inline constexpr char kEnvironmentRotate[] = "env rotate";  ///< --env-rotate: degrees
// The camera parts given over the scene's (CameraOverride), recorded only when given.
inline constexpr char kUpAxis[] = "up axis";          ///< --up: "z", "-y", ...
inline constexpr char kCameraFrom[] = "camera from";  ///< --camera-from: "X,Y,Z"
inline constexpr char kCameraAt[] = "camera at";      ///< --camera-at: "X,Y,Z"
inline constexpr char kCameraUp[] = "camera up";      ///< --camera-up: "X,Y,Z"
inline constexpr char kFov[] = "fov";                 ///< --fov: degrees
inline constexpr char kOrbit[] = "orbit";             ///< --orbit: degrees

}  // namespace raylab::setting_name
