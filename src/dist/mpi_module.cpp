// The MPI module (libraylab_mpi): MPI's channel and session, loaded by MpiSession only for a run
// under an MPI launcher (mpi_backend.h).

#include <mpi.h>

#include <chrono>
#include <cstdlib>
#include <list>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "mpi_backend.h"

namespace raylab::dist {
namespace {

using Clock = std::chrono::steady_clock;

// Point-to-point messages over MPI_COMM_WORLD. Sends are non-blocking, each buffer kept until
// MPI is done with it: two ranks that send each other large messages at the same moment would
// otherwise both wait in MPI_Send for the other to receive.
class MpiChannel final : public Channel {
 public:
  MpiChannel() {
    MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &m_size);
  }

  int rank() const override { return m_rank; }
  int size() const override { return m_size; }

  void send(int to, int tag, std::vector<std::uint8_t> bytes) override {
    m_sending.push_back(Pending{std::move(bytes), MPI_REQUEST_NULL});
    Pending& p = m_sending.back();
    MPI_Isend(p.bytes.data(), static_cast<int>(p.bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD, &p.request);
    progress_sends();
  }

  std::optional<Message> receive(double seconds) override {
    const auto start = Clock::now();
    while (true) {
      progress_sends();
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      if (flag != 0) {
        int count = 0;
        MPI_Get_count(&status, MPI_BYTE, &count);
        Message m{status.MPI_SOURCE, status.MPI_TAG, std::vector<std::uint8_t>(static_cast<std::size_t>(count))};
        MPI_Recv(m.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        return m;
      }
      if (std::chrono::duration<double>(Clock::now() - start).count() >= seconds) return std::nullopt;
      // Polling with short sleeps, not a blocking receive: MPI's blocking calls spin, and a
      // spinning message loop would take a core from the render threads.
      std::this_thread::sleep_for(std::chrono::microseconds(1000));
    }
  }

  void flush(double seconds) override {
    const auto start = Clock::now();
    while (!m_sending.empty() && std::chrono::duration<double>(Clock::now() - start).count() < seconds) {
      progress_sends();
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }

 private:
  struct Pending {
    std::vector<std::uint8_t> bytes;
    MPI_Request request;
  };

  // Frees the buffers of the sends MPI has finished with.
  void progress_sends() {
    for (auto it = m_sending.begin(); it != m_sending.end();) {
      int done = 0;
      MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
      it = done != 0 ? m_sending.erase(it) : std::next(it);
    }
  }

  int m_rank = 0;
  int m_size = 1;
  std::list<Pending> m_sending;  // a list: MPI holds pointers into each buffer until done
};

// MPI initialised for the life of the object; one thread makes MPI calls, the one that made it.
class MpiRun final : public MpiBackend {
 public:
  MpiRun() {
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
      throw std::runtime_error("MPI failed to start");
    }
    // A failing call returns its error here instead of ending the job unexplained.
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    m_channel = std::make_unique<MpiChannel>();
  }

  ~MpiRun() override {
    m_channel.reset();
    MPI_Finalize();
  }

  Channel& channel() override { return *m_channel; }

  std::string host() const override {
    char name[MPI_MAX_PROCESSOR_NAME] = {};
    int length = 0;
    MPI_Get_processor_name(name, &length);
    return std::string(name, static_cast<std::size_t>(length));
  }

  [[noreturn]] void abort(int code) override {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::abort();  // (MPI_Abort does not return)
  }

 private:
  std::unique_ptr<MpiChannel> m_channel;
};

}  // namespace
}  // namespace raylab::dist

/// The module's entry point (mpi_backend.h, kMpiBackendSymbol): the one symbol it exports.
extern "C" __attribute__((visibility("default"))) raylab::dist::MpiBackend* raylab_mpi_backend() {
  return new raylab::dist::MpiRun();
}
