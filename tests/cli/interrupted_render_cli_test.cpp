// An interrupted render never replaces a finished image (issue 21, item 4): with a real SIGINT
// through the real binary, an image that was there before stays as it was and the partial image
// goes beside it (NAME.partial.EXT); a new target gets the partial image itself; once --passes has
// written a whole pass of this render there, the target takes the partial image; a completed
// render removes a partial image left beside it. On a terminal, a second SIGINT ends the progress
// line with a newline, and the bar never wraps in 50 columns.

#include <poll.h>
#include <pty.h>
#include <sys/ioctl.h>

#include <chrono>
#include <thread>

#include "background_process.h"
#include "cli_fixture.h"
#include "raylab/io/image_io.h"

namespace raylab::cli_test {
namespace {

// 4 tiles of one second or more each on one thread: a signal lands in the middle of the render.
const std::string kSlow = "render demo --width 64 --height 16 --spp 1024 --threads 1 -q";

class Interrupted : public Cli {
 protected:
  // Runs `command` and sends SIGINT after a wait, longer each time until `until` exists (a
  // signal before the render starts ends the run with nothing written); checks `unchanged`,
  // if given, after every run. Returns stderr of the last run.
  std::string interrupt_until(const std::string& command, const std::string& until, const std::string& unchanged = "",
                              const std::string& before = "") {
    std::string err;
    for (int wait_ms = 300; wait_ms <= 4800 && !fs::exists(until); wait_ms *= 2) {
      const Background render(split(command), work() / "e.txt");
      std::this_thread::sleep_for(std::chrono::milliseconds(wait_ms));
      render.signal(SIGINT);
      EXPECT_EQ(render.wait(), 130);
      err = read_text(work() / "e.txt");
      if (!unchanged.empty()) {
        EXPECT_EQ(read_text(unchanged), before) << "after " << wait_ms << " ms: " << err;
      }
    }
    return err;
  }
};

TEST_F(Interrupted, AnImageThatWasThereIsKeptAndThePartialImageGoesBesideIt) {
  const std::string good = out_file("good.png"), partial = out_file("good.partial.png");
  ASSERT_EQ(run("render demo --width 64 --height 16 --spp 1 -q -o " + good).code, 0);
  const std::string before = read_text(good);
  const std::string err = interrupt_until(kSlow + " -o " + good, partial, good, before);
  ASSERT_TRUE(fs::exists(partial)) << err;
  EXPECT_NE(err.find("wrote the partial image " + partial + " and the checkpoint"), std::string::npos) << err;
  EXPECT_NE(err.find(good + " was there before this render and is left as it was"), std::string::npos) << err;
  EXPECT_NE(err.find("(black in the image)"), std::string::npos) << err;
  const Film image = read_image(partial);
  EXPECT_EQ(image.width(), 64);
  EXPECT_EQ(image.height(), 16);
  EXPECT_TRUE(fs::exists(out_file("good.ckpt"))) << "the checkpoint message stays true";
}

TEST_F(Interrupted, ANewTargetTakesThePartialImage) {
  const std::string image = out_file("new.png");
  const std::string err = interrupt_until(kSlow + " -o " + image, image);
  ASSERT_TRUE(fs::exists(image)) << err;
  EXPECT_FALSE(fs::exists(out_file("new.partial.png")));
  EXPECT_NE(err.find("wrote the partial image " + image + " and the checkpoint"), std::string::npos) << err;
  EXPECT_EQ(err.find("left as it was"), std::string::npos) << err;
}

TEST_F(Interrupted, OnceAPassIsWrittenTheTargetTakesThePartialImage) {
  const std::string image = out_file("p.png");
  ASSERT_EQ(run("render demo --width 32 --height 16 --spp 1 -q -o " + image).code, 0);
  const std::string before = read_text(image);
  // Not -q: the line of the first pass says when the target holds this render's image.
  const Background render(split("render demo --width 32 --height 16 --spp 1024 --threads 1 --passes 2 -o " + image),
                          work() / "e.txt");
  std::string err;
  for (int i = 0; i < 600 && err.find("pass 1/2: wrote") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    err = read_text(work() / "e.txt");
  }
  ASSERT_NE(err.find("pass 1/2: wrote " + image), std::string::npos) << err;
  EXPECT_NE(read_text(image), before) << "the first pass replaced the old image";
  render.signal(SIGINT);
  const int code = render.wait();
  err = read_text(work() / "e.txt");
  if (code == 0) GTEST_SKIP() << "the second pass finished before the signal: " << err;
  EXPECT_EQ(code, 130) << err;
  EXPECT_FALSE(fs::exists(out_file("p.partial.png")));
  EXPECT_NE(err.find("wrote the partial image " + image + " and the checkpoint"), std::string::npos) << err;
}

TEST_F(Interrupted, ACompletedRenderRemovesAPartialImageLeftBesideIt) {
  write_text(out() / "x.partial.png", "left by an interrupted run");
  const CliResult r = run("render demo --width 16 --height 16 -o " + out_file("x.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out() / "x.partial.png"));
  EXPECT_NE(r.err.find("removed the partial image " + out_file("x.partial.png")), std::string::npos) << r.err;
}

// raylab on a pseudo-terminal of `columns` columns, so that it draws its bar.
class OnTerminal {
 public:
  OnTerminal(const std::vector<std::string>& args, int columns) {
    winsize size{};
    size.ws_row = 24;
    size.ws_col = static_cast<unsigned short>(columns);
    m_pid = ::forkpty(&m_master, nullptr, nullptr, &size);
    if (m_pid == 0) {
      exec_raylab(args);
    }
  }
  ~OnTerminal() { ::close(m_master); }
  // Reads what the program wrote until `text` appears, the program ends, or `seconds` pass.
  void read_until(const std::string& text, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (m_output.find(text) == std::string::npos && std::chrono::steady_clock::now() < end) {
      pollfd p{m_master, POLLIN, 0};
      if (::poll(&p, 1, 100) <= 0) continue;
      char buf[4096];
      const ssize_t n = ::read(m_master, buf, sizeof buf);
      if (n <= 0) return;  // EIO: the program has ended
      m_output.append(buf, static_cast<std::size_t>(n));
    }
  }
  void signal(int sig) const { ::kill(m_pid, sig); }
  int wait() {
    read_until("\x01never", 30.0);
    int status = 0;
    ::waitpid(m_pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  const std::string& output() const { return m_output; }

 private:
  int m_master = -1;
  pid_t m_pid = -1;
  std::string m_output;
};

TEST_F(Interrupted, ASecondSignalEndsTheBarsLineAndTheBarFitsFiftyColumns) {
  // 4 tiles of several seconds each on one thread: both signals land in the second tile.
  OnTerminal render(split("render demo --width 32 --height 32 --spp 4096 --threads 1 -o " + out_file("t.png")), 50);
  render.read_until("ETA", 120.0);  // the bar is drawn once the first tile is done
  ASSERT_NE(render.output().find("ETA"), std::string::npos) << render.output();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  render.signal(SIGINT);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  render.signal(SIGINT);
  EXPECT_EQ(render.wait(), 130);
  const std::string& text = render.output();
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << text;
  EXPECT_EQ(text.find("interrupted by SIGINT"), std::string::npos) << "the second signal ended the run: " << text;
  // Every bar as drawn (between carriage returns and newlines, without clear-to-end) fits in 49
  // columns: nothing wraps.
  std::string line;
  for (char c : text + "\n") {
    if (c == '\r' || c == '\n') {
      const std::size_t clear = line.find("\x1b[K");
      if (clear != std::string::npos) line.erase(clear, 3);
      if (line.find("ETA") != std::string::npos) {
        EXPECT_LE(line.size(), 49u) << line;
      }
      line.clear();
    } else {
      line += c;
    }
  }
}

}  // namespace
}  // namespace raylab::cli_test
