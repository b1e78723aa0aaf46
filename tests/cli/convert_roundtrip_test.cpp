// `raylab convert` through the real binary: a scene file output that reads back to the same
// scene and the same image, an OBJ output with its MTL, and the warning that lists what a
// target format cannot carry.

#include <gtest/gtest.h>

#include <string>

#include "../test_paths.h"
#include "cli_fixture.h"
#include "raylab/io/mtl_writer.h"
#include "raylab/io/scene_loader.h"

namespace raylab {
namespace {

using namespace cli_test;

// Bit-for-bit equality of what the renderer reads from two scenes (object ids may differ: the
// reader makes one object per analytic shape; the material each primitive gets must not).
void expect_same_scene(const Scene& a, const Scene& b) {
  const Geometry &g = a.geometry, &h = b.geometry;
  ASSERT_EQ(g.triangles.size(), h.triangles.size());
  ASSERT_EQ(g.spheres.size(), h.spheres.size());
  ASSERT_EQ(g.cylinders.size(), h.cylinders.size());
  ASSERT_EQ(g.triangle_normals.size(), h.triangle_normals.size());
  ASSERT_EQ(g.triangle_uvs.size(), h.triangle_uvs.size());
  for (std::size_t i = 0; i < g.triangles.size(); ++i) {
    const Triangle &s = g.triangles[i], &t = h.triangles[i];
    ASSERT_TRUE(s.p0 == t.p0 && s.p1 == t.p1 && s.p2 == t.p2) << "triangle " << i;
    if (!g.triangle_normals.empty()) {
      ASSERT_TRUE(g.triangle_normals[i] == h.triangle_normals[i]) << "normals " << i;
    }
  }
  for (std::size_t i = 0; i < g.spheres.size(); ++i) {
    ASSERT_TRUE(g.spheres[i].center == h.spheres[i].center && g.spheres[i].radius == h.spheres[i].radius) << i;
  }
  for (std::size_t i = 0; i < g.cylinders.size(); ++i) {
    const Cylinder &s = g.cylinders[i], &t = h.cylinders[i];
    ASSERT_TRUE(s.base == t.base && s.apex == t.apex && s.base_radius == t.base_radius &&
                s.apex_radius == t.apex_radius)
        << i;
  }
  for (std::uint32_t id = 0; id < g.size(); ++id) {
    const Material &m = a.material_of(id), &n = b.material_of(id);
    ASSERT_TRUE(m.color == n.color && m.kd == n.kd && m.ks == n.ks && m.shininess == n.shininess &&
                m.reflectivity == n.reflectivity && m.transmittance == n.transmittance && m.ior == n.ior &&
                m.fresnel == n.fresnel)
        << "material of primitive " << id;
  }
  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (std::size_t i = 0; i < a.lights.size(); ++i) {
    EXPECT_TRUE(a.lights[i].position == b.lights[i].position && a.lights[i].intensity == b.lights[i].intensity) << i;
  }
  EXPECT_TRUE(a.camera.from == b.camera.from && a.camera.at == b.camera.at && a.camera.up == b.camera.up);
  EXPECT_EQ(a.camera.vfov_degrees, b.camera.vfov_degrees);
  EXPECT_EQ(a.camera.hither, b.camera.hither);
  EXPECT_EQ(a.camera.fov_span, b.camera.fov_span);
  EXPECT_EQ(a.settings.width, b.settings.width);
  EXPECT_EQ(a.settings.height, b.settings.height);
  EXPECT_EQ(a.settings.max_depth, b.settings.max_depth);
  EXPECT_TRUE(a.settings.background == b.settings.background);
}

class ConvertCli : public Cli {
 protected:
  // Converts `source` to `name` in out(); returns stderr.
  std::string convert(const std::string& source, const std::string& name, const std::string& flags = "") {
    const CliResult r = run("convert '" + source + "' '" + out_file(name) + "' " + flags);
    EXPECT_EQ(r.code, 0) << r.err;
    return r.err;
  }
  // The PNG bytes of `source` rendered small, with the same flags every time.
  std::string render(const std::string& source, const std::string& name) {
    const CliResult r = run("render '" + source + "' -o '" + out_file(name) + "' --width 40 --height 32 -q");
    EXPECT_EQ(r.code, 0) << r.err;
    return read_text(out() / name);
  }
};

// NFF sources (polygons and patches with shading normals: teapot; many materials: gears; spheres
// and cones: balls, tree) become scene files that give the very same image.
TEST_F(ConvertCli, SceneFileOutputRendersTheSameImageAsItsSource) {
  for (const std::string spd : {"teapot", "gears", "balls", "tree"}) {
    SCOPED_TRACE(spd);
    convert("spd:" + spd + "?size=1", spd + ".nff", "-q");
    const std::string nff = out_file(spd + ".nff");
    convert(nff, spd + ".json", "-q");
    const std::string before = render(nff, spd + "-nff.png");
    const std::string after = render(out_file(spd + ".json"), spd + "-json.png");
    ASSERT_FALSE(before.empty());
    EXPECT_TRUE(before == after) << "the converted scene renders differently";
    expect_same_scene(load_scene(nff), load_scene(out_file(spd + ".json")));
  }
}

TEST_F(ConvertCli, SceneFileKeepsShadingNormalsAndWritesOneSidecarPerRunOfTriangles) {
  convert("spd:teapot?size=1", "tp.json", "-q");
  const Scene source = load_scene("spd:teapot?size=1");
  ASSERT_FALSE(source.geometry.triangle_normals.empty());
  expect_same_scene(source, load_scene(out_file("tp.json")));
  const std::string json = read_text(out() / "tp.json");
  EXPECT_NE(json.find("\"file\": \"tp.0.ply\""), std::string::npos) << json;
  EXPECT_TRUE(fs::exists(out() / "tp.0.ply"));
}

// Every shipped scene, the textured one included (its image goes to a PNG beside the scene
// file), converts to a scene file that renders the same image, with no warning.
TEST_F(ConvertCli, ShippedScenesConvertToSceneFilesThatRenderTheSameImage) {
  for (const std::string name : {"shapes", "instances", "textured", "whitted", "orbit", "maps"}) {
    SCOPED_TRACE(name);
    const std::string source = raylab::test::source_dir() + "/scenes/" + name + ".json";
    EXPECT_EQ(convert(source, name + ".json"), "");
    EXPECT_TRUE(render(source, name + "-a.png") == render(out_file(name + ".json"), name + "-b.png"));
  }
  EXPECT_TRUE(fs::exists(out() / "textured.tex0.png"));
  EXPECT_NE(read_text(out() / "textured.json").find(R"("texture": {"type": "image", "file": "textured.tex0.png"})"),
            std::string::npos);
  // The maps go beside the scene file too, as linear data where they are data.
  const std::string maps = read_text(out() / "maps.json");
  EXPECT_NE(maps.find(R"("normal": {"file": "maps.tex)"), std::string::npos) << maps;
  EXPECT_NE(maps.find(R"("bump": {"file": "maps.tex)"), std::string::npos) << maps;
  EXPECT_TRUE(fs::exists(out() / "maps.tex1.png"));
}

TEST_F(ConvertCli, ObjOutputWritesItsMtlAndReadsBackWithTheSameMaterials) {
  convert("spd:balls?size=1", "b.obj", "--segments 6 -q");
  const std::string obj = read_text(out() / "b.obj");
  EXPECT_EQ(obj.rfind("# written by raylab\nmtllib b.mtl\n", 0), 0u) << obj.substr(0, 80);
  EXPECT_NE(obj.find("usemtl f1\n"), std::string::npos);
  ASSERT_TRUE(fs::exists(out() / "b.mtl"));
  const Scene source = load_scene("spd:balls?size=1");
  const Scene back = load_scene(out_file("b.obj"));
  for (const Material& m : source.materials) {
    SCOPED_TRACE(m.name);
    const Material* read = nullptr;
    for (const Material& n : back.materials) read = n.name == m.name ? &n : read;
    ASSERT_NE(read, nullptr);
    // MTL has no kd: Kd is the colour times kd, the product the renderer uses.
    EXPECT_TRUE(read->color == m.color * m.kd);
    EXPECT_EQ(read->kd, 1.f);
    EXPECT_EQ(read->ks, m.ks);
    EXPECT_EQ(read->shininess, m.shininess);
    EXPECT_EQ(read->reflectivity, m.reflectivity);  // illum 3 when reflective: the mirror colour is Ks
    EXPECT_EQ(read->transmittance, m.transmittance);
    EXPECT_EQ(read->ior, m.ior);
  }
}

TEST_F(ConvertCli, MaterialNamesAreMadeDistinctAndFreeOfSpaces) {
  Scene s;
  for (const char* name : {"a b", "a_b", "", "a_b"}) s.add_material(Material{.name = name});
  EXPECT_EQ(export_material_names(s), (std::vector<std::string>{"a_b", "a_b~2", "material", "a_b~3"}));
}

TEST_F(ConvertCli, WarningListsWhatEachFormatCannotCarry) {
  const std::string balls = "spd:balls?size=1";  // 10 spheres, polygons, 3 lights, 2 materials
  EXPECT_EQ(convert(balls, "b.ply", "--segments 6"),
            "warning: " + out_file("b.ply") +
                " cannot carry: camera, 3 lights, 2 materials, 2 objects, render settings (size, background), "
                "10 spheres (tessellated)\n");
  EXPECT_EQ(convert(balls, "b.obj", "--segments 6"),
            "warning: " + out_file("b.obj") +
                " cannot carry: camera, 3 lights, render settings (size, background), 10 spheres (tessellated)\n");
  EXPECT_EQ(convert(balls, "b.nff"), "");
  EXPECT_EQ(convert(balls, "b.json"), "");
  EXPECT_EQ(convert(balls, "q.ply", "-q"), "");  // quiet: no warning either

  // What NFF and the scene format lack: a directional light, falloff, a checker texture, an
  // ambient term, a disk.
  write_text(work() / "s.json", R"({"version": 1,
    "camera": {"from": [0, 0, 5], "at": [0, 0, 0]},
    "render": {"ambient": 0.1, "spp": 4},
    "materials": {"c": {"texture": {"type": "checker"}}, "m": {"reflectivity": 0.5, "fresnel": false}},
    "lights": [{"type": "directional", "direction": [0, -1, 0]}, {"type": "point", "position": [0, 5, 0], "falloff": true}],
    "objects": [{"type": "disk", "material": "c", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1},
                {"type": "sphere", "material": "m", "center": [0, 0, 0], "radius": 0.5}]})");
  const std::string scene = (work() / "s.json").string();
  EXPECT_EQ(convert(scene, "s.nff"), "warning: " + out_file("s.nff") +
                                         " cannot carry: 1 directional or area light (as point lights), falloff of 1 "
                                         "light, 1 checker texture, separate highlight and mirror weights of 1 "
                                         "material, fresnel off in 1 material, render settings (spp, ambient), 1 "
                                         "disk (as 32-gons)\n");
  EXPECT_EQ(convert(scene, "s.obj", "--segments 6"),
            "warning: " + out_file("s.obj") +
                " cannot carry: camera, 2 lights, mirror weight of 1 material, fresnel off in 1 material, 1 checker "
                "texture, render settings (spp, ambient), 1 sphere (tessellated), 1 disk (tessellated)\n");
  EXPECT_EQ(convert(scene, "s.json"), "");

  // A bare mesh's camera, lights and grey material are the loader's, not the source's.
  write_text(work() / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(convert((work() / "tri.obj").string(), "tri.ply"), "");
}

TEST_F(ConvertCli, AnOutputFormatItCannotWriteIsAUsageErrorListingTheFormats) {
  const CliResult r = run("convert demo '" + out_file("x.xyz") + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("(supported: .json .nff .obj .ply)"), std::string::npos) << r.err;
  expect_out_empty();
}

}  // namespace
}  // namespace raylab
