#pragma once
// Internal to the render module: the packet path of the uniform samplers. Primary rays go to the
// accelerator in coherent groups of up to 16, then the shadow rays of those hits toward each
// single-sample light (point, directional) go as one any-hit group per light; everything else
// (area-light samples, reflection, refraction) is traced ray by ray as before. Each lane is
// shaded by WhittedIntegrator::shade with the same seed, the same ray order and the same
// arithmetic as the single-ray path, so the image and the ray counts are bit-identical.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "raylab/render/camera.h"
#include "raylab/render/whitted.h"
#include "raylab/sampling/pixel_sampler.h"
#include "render_workers.h"

namespace raylab::detail {

/// Most rays in one packet: the widest packet kernel (AVX-512, 16 lanes); an 8-wide kernel takes
/// a packet as two halves.
inline constexpr int kPacketSize = 16;

/// Side of the square pixel blocks whose samples make up a packet at `spp` samples per pixel:
/// 4 at 1 spp (a 4x4 block, 16 rays), 2 at 2 to 4 spp (a 2x2 block, each pixel's samples
/// consecutive: 16 rays at 4 spp), 1 above (one pixel's samples, then the next pixel's). Small
/// blocks keep the rays of a packet close in direction, which is what packet traversal needs.
int packet_block_side(int spp);

/// Traces the primary rays of up to kPacketSize lanes as packets. Reuses its buffers from one
/// packet to the next; one per worker task (not thread-safe).
class PrimaryPacketTracer {
 public:
  /// A tracer for `ctx` (whose scene must not change while the tracer lives). With
  /// `replace_nonfinite` a NaN or infinite radiance becomes black and is counted (as the pixel
  /// loops' finite_radiance does); without it the value is handed on as it is (the SPD protocol,
  /// whose single-ray loop keeps the integrator's value).
  explicit PrimaryPacketTracer(const TraceContext& ctx, bool replace_nonfinite = true);

  /// Radiance along each of `rays` (primary rays, at most kPacketSize), into `out`; lane i draws
  /// its random numbers from Pcg32(seeds[i]). Counts every ray it casts in ctx.stats. With
  /// ctx.count_traversal the accelerator has no counted packet entry point, so the same groups
  /// are traced one by one through the counted kernels (the counts stay those of single rays).
  void trace(std::span<const Ray> rays, std::span<const std::uint64_t> seeds, std::span<Color> out);

 private:
  // Any-hit answers for the shadow rays of the lanes that cast one toward single-sample light
  // `light`, stored with the light sample as each lane's DecidedShadow for that light.
  void trace_shadows(std::size_t light, std::size_t lanes);

  // The radiance `c` of a lane as it is handed on (see replace_nonfinite).
  Color handed_on(Color c) const { return m_replace_nonfinite ? finite_radiance(m_ctx, c) : c; }

  const TraceContext& m_ctx;
  bool m_replace_nonfinite;
  std::vector<std::size_t> m_single_lights;  // indices of the lights whose shadow rays go as packets
  std::array<Ray, kPacketSize> m_rays;
  std::array<Hit, kPacketSize> m_hits;
  std::array<SurfaceInteraction, kPacketSize> m_surfaces;
  std::array<ShadingPoint, kPacketSize> m_points;  // m_surfaces as light sampling sees them
  std::array<Ray, kPacketSize> m_shadow_rays;
  std::array<std::uint8_t, kPacketSize> m_shadow_lane;  // lane of each gathered shadow ray
  std::array<std::uint8_t, kPacketSize> m_blocked;
  std::vector<DecidedShadow> m_answers;  // lane * light count + light
};

/// The uniform pixel loop of one tile, with its primary rays traced as packets: the colour of
/// every sample of every pixel, handed over pixel by pixel in row-major order (the order the
/// single-ray loop accumulates in, which wider filters need for the same sums).
class TilePacketTracer {
 public:
  /// Samples [first_sample, end_sample) of every pixel (of the `sampler.spp()`), placed by
  /// `sampler`, rays made by `camera`, traced in `ctx`.
  TilePacketTracer(const TraceContext& ctx, const Camera& camera, const PixelSampler& sampler, int first_sample,
                   int end_sample);

  /// Calls `on_pixel(px, py, colors)` for every pixel of `tile` in row-major order, `colors[k]`
  /// being the radiance of sample first_sample + k of that pixel.
  template <class Fn>
  void for_each_pixel(const PixelRect& tile, Fn&& on_pixel) {
    for (const PixelRect& unit : units(tile)) {
      trace_unit(unit);
      const int count = sample_count();
      const int width = unit.x1 - unit.x0;
      for (int py = unit.y0; py < unit.y1; ++py) {
        for (int px = unit.x0; px < unit.x1; ++px) {
          const std::size_t first = (std::size_t(py - unit.y0) * width + (px - unit.x0)) * count;
          on_pixel(px, py, std::span<const Color>(m_colors).subspan(first, static_cast<std::size_t>(count)));
        }
      }
    }
  }

 private:
  // The tile cut into the rectangles traced (and then handed over) at once: bands of one block
  // row, or single pixels when one pixel has a packet's worth of samples (memory stays bounded
  // by a band of 16 samples per column, or by one pixel's samples).
  std::vector<PixelRect> units(const PixelRect& tile) const;
  // Traces every sample of `unit`, block by block, into m_colors (pixel row-major, then sample).
  void trace_unit(const PixelRect& unit);
  // Traces the pending lanes as one packet and stores their colours.
  void flush();
  // Samples traced per pixel.
  int sample_count() const { return m_end_sample - m_first_sample; }

  const Camera& m_camera;
  const PixelSampler& m_sampler;
  int m_first_sample, m_end_sample;
  PrimaryPacketTracer m_tracer;
  std::vector<Color> m_colors;
  int m_count = 0;                                 // pending lanes
  std::array<Ray, kPacketSize> m_rays;             // pending primary rays
  std::array<std::uint64_t, kPacketSize> m_seeds;  // their path seeds
  std::array<std::size_t, kPacketSize> m_slots;    // where their colours go in m_colors
  std::array<Color, kPacketSize> m_out;
};

}  // namespace raylab::detail
