#pragma once
// A raylab process started in the background for the tests that signal it mid-render (see
// long_render_cli_test.cpp and interrupted_render_cli_test.cpp).

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../test_paths.h"

namespace raylab::cli_test {

// In a forked child: becomes `raylab args` (exit 127 if that fails).
[[noreturn]] inline void exec_raylab(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  std::string binary = raylab::test::raylab_binary();
  argv.push_back(binary.data());
  std::vector<std::string> copy = args;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  ::execv(binary.c_str(), argv.data());
  ::_exit(127);
}

// A raylab process started in the background, its streams going to files in `work`.
class Background {
 public:
  Background(const std::vector<std::string>& args, const std::filesystem::path& err) {
    m_pid = ::fork();
    if (m_pid == 0) {
      const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(fd, STDERR_FILENO);
      ::dup2(fd, STDOUT_FILENO);
      exec_raylab(args);
    }
  }
  void signal(int sig) const { ::kill(m_pid, sig); }
  // The exit status, or 128 + the signal that killed it.
  int wait() const {
    int status = 0;
    ::waitpid(m_pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

 private:
  pid_t m_pid = -1;
};

// The words of `s`, split at spaces (a command line without quoting).
inline std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::string word;
  for (char c : s + " ") {
    if (c == ' ') {
      if (!word.empty()) out.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  return out;
}

}  // namespace raylab::cli_test
