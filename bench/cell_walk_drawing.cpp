// One ray's walk through the space-subdivision structures, drawn on a 2D slice
// (docs/accelerators.md): a flat scene of spheres centred in the plane z = 0 — a dense cluster
// in one corner of a large, mostly empty square, the teapot-in-a-stadium situation in 2D — and
// one ray in the plane z = Z0 aimed across the empty part into the cluster. For each structure
// named, one panel: the spheres' cross-sections, every cell the closest-hit query visits (from
// the structure's own CellWalk, i.e. the real traversal; shaded where the walk tested
// primitives), the ray up to its hit, and the number of cells and primitive tests.
//
//   raylab_cell_walk_drawing OUT.svg [STRUCTURE ...]   (default: grid grid2 irregular octree)

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "raylab/accel/cell_walk.h"
#include "raylab/accel/factory.h"
#include "raylab/core/rng.h"
#include "raylab/io/atomic_file.h"

namespace {

using namespace raylab;

constexpr float kSide = 100.f;  // the scene square: [0, kSide]^2 in x and y
constexpr float kZ0 = 0.05f;    // the slice: off z = 0, so the ray does not run along a cell face
constexpr double kPanel = 360.0;
constexpr double kMargin = 12.0;
constexpr double kTitle = 34.0;

// 400 small spheres packed into the corner square [70, 95]^2, and 12 larger ones scattered over
// two strips of the rest: the cluster is what makes a uniform grid either too coarse there or too fine
// everywhere else.
Geometry flat_scene() {
  Geometry g;
  Pcg32 s(22, 1);
  for (int i = 0; i < 400; ++i) {
    const float x = 70.f + 25.f * s.next_float(), y = 70.f + 25.f * s.next_float();
    g.add(Sphere{{x, y, 0.f}, 0.25f + 0.35f * s.next_float()}, 0);
  }
  // Away from the drawn ray, so that it crosses the empty middle and ends in the cluster.
  for (int i = 0; i < 12; ++i) {
    const bool low = i % 2 == 0;
    const float x = 5.f + (low ? 55.f : 35.f) * s.next_float();
    const float y = low ? 5.f + 25.f * s.next_float() : 80.f + 15.f * s.next_float();
    g.add(Sphere{{x, y, 0.f}, 1.5f + 2.5f * s.next_float()}, 0);
  }
  return g;
}

struct Panel {
  std::string name;
  std::vector<WalkedCell> cells;
  float hit_t = 0.f;
  bool hit = false;
  std::uint64_t prim_tests = 0;
};

double sx(double x, int panel) { return kMargin + panel * (kPanel + kMargin) + x / kSide * kPanel; }
double sy(double y) { return kTitle + kPanel - y / kSide * kPanel; }  // y up

std::string draw(const Geometry& g, const Ray& ray, const std::vector<Panel>& panels) {
  const double width = kMargin + panels.size() * (kPanel + kMargin);
  const double height = kTitle + kPanel + kMargin + 18.0;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" "
      "font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      width, height);
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const int i = static_cast<int>(p);
    const Panel& panel = panels[p];
    svg += fmt::format("<text x=\"{:.1f}\" y=\"16\" font-weight=\"bold\">--accel {}</text>\n", sx(0, i), panel.name);
    svg += fmt::format("<text x=\"{:.1f}\" y=\"30\">{} cells visited, {} primitive tests</text>\n", sx(0, i),
                       panel.cells.size(), panel.prim_tests);
    svg += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" "
        "stroke=\"#999\"/>\n",
        sx(0, i), sy(kSide), kPanel, kPanel);
    // The cells first, so the spheres and the ray are drawn over them.
    for (const WalkedCell& c : panel.cells) {
      const double x0 = sx(std::max(c.box.lo.x, 0.f), i), x1 = sx(std::min(c.box.hi.x, kSide), i);
      const double y0 = sy(std::min(c.box.hi.y, kSide)), y1 = sy(std::max(c.box.lo.y, 0.f));
      svg += fmt::format(
          "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"{}\" stroke=\"#1f77b4\" "
          "stroke-width=\"0.8\"/>\n",
          x0, y0, std::max(x1 - x0, 0.3), std::max(y1 - y0, 0.3), c.has_primitives ? "#ffd8a8" : "#e8f0fa");
    }
    for (const Sphere& s : g.spheres) {
      const double r = std::sqrt(std::max(0.0, double(s.radius) * s.radius - double(kZ0) * kZ0));
      svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"#555\" fill-opacity=\"0.45\"/>\n",
                         sx(s.center.x, i), sy(s.center.y), r / kSide * kPanel);
    }
    const float t_end = panel.hit ? panel.hit_t : 2.f * kSide;
    const Vec3 a = ray.origin, b = ray.at(t_end);
    svg += fmt::format(
        "<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" stroke=\"#d62728\" "
        "stroke-width=\"1.6\"/>\n",
        sx(a.x, i), sy(a.y), sx(b.x, i), sy(b.y));
    if (panel.hit) {
      svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3\" fill=\"#d62728\"/>\n", sx(b.x, i), sy(b.y));
    }
  }
  svg += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"#555\">Slice z = {} of {} spheres centred at z = 0. Boxes: the "
      "cells one closest-hit query visits (orange: primitives tested there).</text>\n",
      kMargin, height - 6.0, kZ0, g.spheres.size());
  svg += "</svg>\n";
  return svg;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: raylab_cell_walk_drawing OUT.svg [STRUCTURE ...]\n");
    return 2;
  }
  try {
    std::vector<std::string> names;
    for (int i = 2; i < argc; ++i) names.emplace_back(argv[i]);
    if (names.empty()) names = {"grid", "grid2", "irregular", "octree"};
    const Geometry g = flat_scene();
    // From the left edge, rising gently into the cluster across the empty middle.
    const Vec3 origin{0.5f, 45.f, kZ0};
    const Vec3 target{82.f, 84.f, kZ0};
    const Ray ray{origin, 0.f, normalize(target - origin)};
    std::vector<Panel> panels;
    for (const std::string& name : names) {
      const auto accel = make_accelerator(name, g);
      const auto* walk = dynamic_cast<const CellWalk*>(accel.get());
      if (walk == nullptr) {
        std::fprintf(stderr, "raylab_cell_walk_drawing: '%s' is not made of cells\n", name.c_str());
        return 2;
      }
      Panel panel{name, walk->cells_on_ray(ray)};
      Ray r = ray;
      Hit hit;
      TraversalStats stats;
      panel.hit = accel->intersect_counted(r, hit, stats);
      panel.hit_t = hit.t;
      panel.prim_tests = stats.prim_tests;
      panels.push_back(std::move(panel));
    }
    write_text_atomically(argv[1], draw(g, ray, panels));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raylab_cell_walk_drawing: %s\n", e.what());
    return 1;
  }
  return 0;
}
