#pragma once
// The command-line test fixture: runs the real raylab binary in a fresh folder and captures its
// exit code and output streams.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>
#include "../test_paths.h"

namespace raylab::cli_test {

namespace fs = std::filesystem;

inline std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_text(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

inline std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

struct CliResult {
  int code = -1;  ///< exit code; -1 when the process did not exit normally
  std::string out, err;
};

// Each test gets `work` (inputs and captured streams) and `out` (where outputs go, and where
// nothing may be left after a failure), both fresh.
class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    m_root = fs::temp_directory_path() / ("raylab-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(m_root);
    fs::create_directories(work());
    fs::create_directories(out());
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(m_root, ec);
  }
  fs::path work() const { return m_root / "work"; }
  fs::path out() const { return m_root / "out"; }
  std::string out_file(const std::string& name) const { return (out() / name).string(); }

  // Runs `raylab args`, with `env` (shell assignments such as "NAME=value") in its environment.
  CliResult run(const std::string& args, const std::string& env = "") const {
    const fs::path so = work() / "stdout.txt", se = work() / "stderr.txt";
    const std::string cmd = (env.empty() ? "" : "env " + env + " ") + "'" + raylab::test::raylab_binary() + "' " +
                            args + " >'" + so.string() + "' 2>'" + se.string() + "'";
    const int status = std::system(cmd.c_str());
    CliResult r;
    if (status != -1 && WIFEXITED(status)) r.code = WEXITSTATUS(status);
    r.out = read_text(so);
    r.err = read_text(se);
    return r;
  }

  // Writes an OBJ file into `work`; returns its path.
  std::string obj(const std::string& name, const std::string& text) const {
    const fs::path p = work() / name;
    write_text(p, text);
    return p.string();
  }

  // A failed render must leave the output folder exactly as it was: empty.
  void expect_out_empty() const { EXPECT_TRUE(entries(out()).empty()) << "left behind: " << entries(out()).front(); }

 private:
  fs::path m_root;
};

}  // namespace raylab::cli_test
