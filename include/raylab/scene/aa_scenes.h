#pragma once
/// \file
/// The antialiasing stress scenes: six built-in test charts on which `raylab quality` compares
/// the pixel samplers. Each is composed so that what a sampler gets wrong is easy to see and to
/// measure: exact shapes, known colours, features from far below to far above the Nyquist limit.
///
/// Common to all six: 640 x 480, 1 sample per pixel, seed 0, the default sampler. The four
/// "unlit" charts (checker, lines, zone plate, edges) have no lights, ambient (1, 1, 1) and
/// kd = 1, so every surface shows exactly its (textured) diffuse colour and every pixel is a
/// coverage-weighted mix of known colours; their ray depth is 1. The lit ones (highlights,
/// whitted) trace to depth 5.
///
/// Pixel-calibrated charts (lines, zone plate, highlights, edges) are laid out in image
/// coordinates: `pixel_camera()` maps the world plane z = 0 onto the image so that world
/// (x, y, 0) lands on image position (x, kAaHeight - y). Image y grows downwards and world y
/// upwards; `aa_pixel_to_world` does that flip, and the charts' layout constants below are in
/// image coordinates (x right, y down, (0, 0) the top-left corner of the top-left pixel).

#include "raylab/core/vec3.h"
#include "raylab/scene/camera_spec.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Image width of every antialiasing chart, in pixels.
inline constexpr int kAaWidth = 640;
/// Image height of every antialiasing chart, in pixels.
inline constexpr int kAaHeight = 480;
/// Distance of the pixel camera from the plane z = 0: far enough that the small depth of the
/// highlight spheres changes their scale by less than 0.1 %.
inline constexpr float kAaCameraDistance = 2000.f;

/// The world point on the plane z = `z` that the pixel camera shows at image position (x, y)
/// (exactly for z = 0; planes behind it are scaled by D / (D - z) about the image centre).
constexpr Vec3 aa_pixel_to_world(float x, float y, float z = 0.f) { return {x, static_cast<float>(kAaHeight) - y, z}; }

/// The pixel camera: at (320, 240, D) looking at (320, 240, 0), up +y, vertical field of view
/// 2 atan(240 / D), so that one world unit of the plane z = 0 is exactly one pixel of a
/// 640 x 480 image (D = kAaCameraDistance).
CameraSpec aa_pixel_camera();

/// aa-checker: eye height above the plane (world units).
inline constexpr float kAaCheckerEyeHeight = 1.5f;
/// aa-checker: side of a checker cell (world units); near cells are about 50 px wide.
inline constexpr float kAaCheckerCell = 0.25f;
/// aa-checker: vertical field of view (degrees).
inline constexpr float kAaCheckerVfov = 50.f;
/// aa-checker: image row of the horizon (a third of the way down).
inline constexpr float kAaCheckerHorizonRow = 160.f;
/// aa-checker: radius of the floor disk (world units); its rim is within 0.2 px of the horizon.
inline constexpr float kAaCheckerFloorRadius = 4000.f;
/// aa-checker: the sky's flat colour.
inline constexpr Color kAaCheckerSky{0.35f, 0.5f, 0.8f};

/// aa-lines: centre of the Siemens star (image coordinates).
inline constexpr Vec2 kAaStarCenter{490.f, 240.f};
/// aa-lines: radius of the Siemens star (pixels).
inline constexpr float kAaStarRadius = 120.f;
/// aa-lines: number of white wedges (as many black gaps alternate with them).
inline constexpr int kAaStarWedges = 64;
/// aa-lines: centre of the ring of thin lines (image coordinates; off the pixel lattice).
inline constexpr Vec2 kAaLinesCenter{180.3f, 240.4f};
/// aa-lines: number of thin lines (odd, so that no two are parallel).
inline constexpr int kAaLineCount = 25;
/// aa-lines: the lines run radially from this distance of kAaLinesCenter ...
inline constexpr float kAaLineInnerRadius = 38.f;
/// aa-lines: ... to this one (so each is 120 px long).
inline constexpr float kAaLineOuterRadius = 158.f;
/// aa-lines: width of the thinnest line (pixels).
inline constexpr float kAaLineMinWidth = 0.1f;
/// aa-lines: width of the widest line (pixels).
inline constexpr float kAaLineMaxWidth = 1.5f;

/// aa-zoneplate: radius of the disc of rings (pixels), centred in the image.
inline constexpr float kAaZonePlateRadius = 180.f;
/// aa-zoneplate: chirp rate k, so that the local frequency k r reaches 0.75 cycles per pixel at
/// the rim (Nyquist, 0.5, is crossed at r = 120 px).
inline constexpr float kAaZonePlateK = 0.75f / kAaZonePlateRadius;

/// aa-highlights: columns of the sphere grid (diameter grows from 0.5 px to 3 px along them).
inline constexpr int kAaHighlightColumns = 11;
/// aa-highlights: rows of the sphere grid (shininess grows from 1000 to 4000 down them).
inline constexpr int kAaHighlightRows = 9;
/// aa-highlights: number of emissive sub-pixel dots.
inline constexpr int kAaDotCount = 40;

/// aa-edges: grey of the right half's background.
inline constexpr float kAaEdgesGreyBackground = 0.50f;
/// aa-edges: grey of the right half's shapes.
inline constexpr float kAaEdgesGreyShape = 0.55f;

/// aa-whitted: side of the square floor (world units); finite, so that its far edge stays
/// where its checker cells are still wider than 7 px.
inline constexpr float kAaWhittedFloorSize = 24.f;
/// aa-whitted: side of a floor checker cell (world units).
inline constexpr float kAaWhittedCell = 1.5f;

/// aa-checker: an unlit black-and-white checkerboard to the horizon under a flat sky. The eye
/// is kAaCheckerEyeHeight above an (almost) infinite floor and turned 30 degrees from the
/// checker axes, so neither family of cell edges is horizontal in the image. Cells run from
/// about 50 px at the bottom of the image to far below a pixel near the horizon (row 160):
/// measures moire and the convergence of a chart whose frequency has no upper bound.
Scene make_aa_checker_scene();

/// aa-lines: unlit white on black. Left: 25 thin lines, each 120 px long, radiating from
/// kAaLinesCenter at 25 directions 7.2 degrees apart (mod 180) with widths 0.1 to 1.5 px
/// (geometric steps, shuffled so that neighbours differ). Right: a Siemens star of 64 white
/// wedges (one triangle each, 2 pi / 128 wide) and 64 black gaps, radius 120 px, turned a
/// quarter wedge so that no edge lies on a pixel row or column; its period 2 pi r / 64 px
/// reaches the Nyquist limit at r = 64 / pi (about 20 px). Measures thin-feature coverage and
/// the aliasing of converging edges.
Scene make_aa_lines_scene();

/// aa-zoneplate: an unlit zone plate (Texture::Kind::kZonePlate, black to white) on a quad
/// covering the frame, centred in the image: rings of local frequency kAaZonePlateK * r cycles
/// per pixel, from 0 at the centre to 0.75 at the rim (r = 180 px), then flat 0.5 grey. One
/// sample per pixel shows phantom rings beyond r = 120 px; measures how samplers trade
/// aliasing for noise.
Scene make_aa_zoneplate_scene();

/// aa-highlights: on black, a grid of 11 x 9 tiny Phong spheres (ks 1, kd 0.3, dark red or dark
/// blue) lit by one point light up and to the left of the camera, so each shows a highlight
/// towards the camera: diameters 0.5 to 3 px by column, shininess 1000 to 4000 by row. Between
/// them, 40 emissive dots 0.2 to 0.8 px across (white or coloured, emission <= 1). Every
/// radiance is at most about 1.2. Measures how samplers find small, bright, isolated features.
Scene make_aa_highlights_scene();

/// aa-edges: unlit polygons with long straight edges of slope 1/10, 1 and 10 (and a rectangle
/// for horizontal and vertical edges), 150 to 300 px long, off the pixel lattice. Left half:
/// white shapes on black. Right half: the same shapes in 0.55 grey on a 0.50 grey background
/// (a quad behind them whose edge is the pixel boundary x = 320). Measures edge antialiasing at
/// high and at low contrast, where adaptive samplers' thresholds matter.
Scene make_aa_edges_scene();

/// aa-whitted: Whitted's scene: a mirror sphere and a glass sphere on a red and yellow checkered
/// floor (24 x 24 units, 1.5-unit cells) under two point lights with shadows and a sky
/// gradient. The camera looks down at 26 degrees; every visible cell is at least 7 px wide, the
/// spheres are about 115 and 120 px across. Measures edges, shadows, reflections and
/// refractions (which shrink the floor far below a pixel) together.
Scene make_aa_whitted_scene();

}  // namespace raylab
