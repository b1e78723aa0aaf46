// Scene errors that point at the fix, through the real binary: a JSON syntax error where it is,
// a missing mesh or texture named at the line that refers to it; a missing part of a model is a
// warning and the rest renders.

#include <gtest/gtest.h>

#include <string>

#include "cli_fixture.h"

namespace raylab {
namespace {

using namespace cli_test;

const std::string kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\nf 1/1 2/2 3/3\n";

TEST_F(Cli, MissingMeshOfASceneFileIsAnErrorAtItsReference) {
  write_text(work() / "s.json",
             "{\"version\": 1,\n \"objects\": [\n   {\"type\": \"mesh\",\n    \"file\": \"nope.obj\"}]}\n");
  const CliResult r = run("render '" + (work() / "s.json").string() + "' -o '" + out_file("x.png") + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("s.json:4:5: mesh file 'nope.obj' not found"), std::string::npos) << r.err;
  expect_out_empty();
}

TEST_F(Cli, MissingTextureOfASceneFileIsAnErrorAtItsReference) {
  write_text(work() / "s.json",
             "{\"version\": 1, \"materials\": {\"m\": {\"texture\": {\"type\": \"image\",\n  \"file\": \"no.png\"}}},\n"
             " \"objects\": [{\"type\": \"sphere\", \"material\": \"m\", \"center\": [0, 0, 0], \"radius\": 1}]}\n");
  const CliResult r = run("render '" + (work() / "s.json").string() + "' -o '" + out_file("x.png") + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("s.json:2:3: texture file 'no.png' not found"), std::string::npos) << r.err;
  expect_out_empty();
}

TEST_F(Cli, MissingTextureOfAModelIsAWarningAtTheMtlLineAndTheModelRenders) {
  write_text(work() / "m.mtl", "newmtl a\nKd 1 1 1\nmap_Kd missing.png\n");
  const std::string obj = this->obj("t.obj", "mtllib m.mtl\n" + kTriangleObj);
  const CliResult r = run("render '" + obj + "' -o '" + out_file("t.png") + "' --width 16 --height 16");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(
      r.err.find("warning: " + (work() / "m.mtl").string() + ":3:8: texture 'missing.png' not found (looked for "),
      std::string::npos)
      << r.err;
  EXPECT_TRUE(fs::exists(out() / "t.png"));
}

TEST_F(Cli, MissingMaterialLibraryIsAWarningAtTheMtllibLineAndTheModelRenders) {
  const std::string obj = this->obj("u.obj", "mtllib nomtl.mtl\n" + kTriangleObj);
  const CliResult r = run("render '" + obj + "' -o '" + out_file("u.png") + "' --width 16 --height 16");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + obj + ":1:8: material library 'nomtl.mtl' not found"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out() / "u.png"));
}

TEST_F(Cli, JsonSyntaxErrorIsReportedAfterTheValueThatNeedsAComma) {
  write_text(work() / "scene.json", "{\"version\": 1,\n  \"render\": {\"width\": 640\n    \"height\": 480}}\n");
  const CliResult r = run("render '" + (work() / "scene.json").string() + "' -o '" + out_file("x.png") + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("scene.json:2:26: expected ',' or '}' after the value of \"width\""), std::string::npos)
      << r.err;
  expect_out_empty();
}

}  // namespace
}  // namespace raylab
