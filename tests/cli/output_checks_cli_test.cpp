// Outputs checked before the work (issue 21, item 5): a folder that cannot be written, a path
// through a file, and an output that is one of the scene's own files (the scene file, a mesh it
// places, an OBJ's material library or texture), by any name, are usage errors (exit 2) that
// name the conflict, and the input is left as it was.

#include "cli_fixture.h"
#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/image_io.h"
#include "raylab/io/scene_loader.h"

namespace raylab::cli_test {
namespace {

class OutputChecks : public Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    Film texture(2, 2);
    texture.at(0, 0) = Color(1.f, 0.f, 0.f);
    write_image(texture, (work() / "tex.png").string());
    write_text(work() / "m.mtl", "newmtl painted\nKd 1 1 1\nmap_Kd tex.png\n");
    obj("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl painted\nf 1/1 2/2 3/3\n");
    write_text(work() / "s.json",
               R"({"version": 1, "camera": {"from": [0.3, 0.3, 3], "at": [0.3, 0.3, 0], "fov": 40},
                   "lights": [{"type": "point", "position": [0, 0, 5]}],
                   "objects": [{"type": "mesh", "file": "m.obj"}]})");
  }
  std::string in(const std::string& name) const { return (work() / name).string(); }

  // `args` is refused with exit 2 and a message naming `file` as the scene's input, which is unchanged.
  void expect_refused_as_input(const std::string& args, const std::string& file) const {
    const std::string before = read_text(in(file));
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("one of the scene's own input files"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(file + "'"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(in(file)), before) << file;
    EXPECT_EQ(r.err.find("wrote"), std::string::npos) << r.err;
  }
};

TEST_F(OutputChecks, TheLoadersListEveryFileTheSceneCameFrom) {
  const Scene scene = load_scene(in("s.json"));
  std::vector<std::string> names;
  for (const std::string& f : scene.source_files) names.push_back(fs::path(f).filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{"s.json", "m.obj", "m.mtl", "tex.png"}));
  EXPECT_TRUE(load_scene("demo").source_files.empty());
}

TEST_F(OutputChecks, AFolderThatCannotBeWrittenIsAUsageError) {
  // /proc refuses new files even to root, for whom access() says yes.
  const CliResult r = run("render demo --width 8 --height 8 -o /proc/x.png");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("cannot write '/proc/x.png': folder '/proc' is not writable"), std::string::npos) << r.err;
  EXPECT_THROW(check_writable("/proc/x.png"), UsageError);
}

TEST_F(OutputChecks, APathThroughAFileIsAUsageErrorNamingTheFile) {
  write_text(out() / "somefile", "kept");
  const std::string target = out_file("somefile") + "/deeper/out.png";
  for (const std::string& args : {"render demo --width 8 --height 8 -o " + target, "convert demo " + target + ".obj",
                                  "compare spd:balls?size=1 --width 8 --height 8 --csv " + target + ".csv"}) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("'" + out_file("somefile") + "' is a file, not a folder"), std::string::npos) << r.err;
  }
  EXPECT_EQ(read_text(out() / "somefile"), "kept");
  // A folder that is missing is still said so.
  const CliResult missing = run("render demo --width 8 --height 8 -o " + out_file("none/out.png"));
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("folder '" + out_file("none") + "' does not exist"), std::string::npos) << missing.err;
}

TEST_F(OutputChecks, ATextureOfTheSceneIsNotOverwrittenByTheImage) {
  expect_refused_as_input("render " + in("s.json") + " --width 8 --height 8 -o " + in("tex.png"), "tex.png");
  expect_refused_as_input("render " + in("m.obj") + " --width 8 --height 8 -o " + in("tex.png"), "tex.png");
  // By another name: a link to it.
  fs::create_symlink(in("tex.png"), work() / "link.png");
  expect_refused_as_input("render " + in("m.obj") + " --width 8 --height 8 -o " + in("link.png"), "tex.png");
  // The sample-count image of --aov samples too.
  fs::rename(work() / "tex.png", work() / "out.samples.png");
  write_text(work() / "m.mtl", "newmtl painted\nKd 1 1 1\nmap_Kd out.samples.png\n");
  expect_refused_as_input("render " + in("m.obj") + " --aov samples --width 8 --height 8 -o " + in("out.png"),
                          "out.samples.png");
}

TEST_F(OutputChecks, TheSceneFileAMeshOrAMaterialLibraryIsNotOverwritten) {
  expect_refused_as_input("convert " + in("m.obj") + " " + in("m.obj"), "m.obj");
  expect_refused_as_input("convert " + in("s.json") + " " + in("m.obj"), "m.obj");
  expect_refused_as_input("compare " + in("s.json") + " --width 8 --height 8 --json " + in("s.json"), "s.json");
  expect_refused_as_input("quality " + in("m.obj") + " --width 8 --height 8 --budgets 1 --cache-dir " +
                              out_file("cache") + " --csv " + in("m.mtl"),
                          "m.mtl");
  expect_refused_as_input("bench " + in("m.obj") + " --width 8 --height 8 --json " + in("m.mtl"), "m.mtl");
  expect_refused_as_input(
      "render " + in("m.obj") + " --width 8 --height 8 -o " + in("x.png") + " --checkpoint " + in("m.mtl"), "m.mtl");
}

TEST_F(OutputChecks, AnOutputBesideTheInputsIsFine) {
  const CliResult r = run("render " + in("s.json") + " --width 8 --height 8 -q -o " + out_file("ok.png"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out_file("ok.png")));
}

}  // namespace
}  // namespace raylab::cli_test
