#include "raylab/dist/local_channel.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>

namespace raylab::dist {
namespace {

// Every rank's mailbox, shared by the channels of one make_local_channels call.
struct Mailboxes {
  explicit Mailboxes(int size) : boxes(static_cast<std::size_t>(size)) {}
  struct Box {
    std::mutex mutex;
    std::condition_variable arrived;
    std::deque<Message> messages;
  };
  std::vector<Box> boxes;
};

class LocalChannel final : public Channel {
 public:
  LocalChannel(std::shared_ptr<Mailboxes> boxes, int rank) : m_boxes(std::move(boxes)), m_rank(rank) {}

  int rank() const override { return m_rank; }
  int size() const override { return static_cast<int>(m_boxes->boxes.size()); }

  void send(int to, int tag, std::vector<std::uint8_t> bytes) override {
    if (m_silent.load()) return;
    Mailboxes::Box& box = m_boxes->boxes.at(static_cast<std::size_t>(to));
    {
      const std::lock_guard lock(box.mutex);
      box.messages.push_back(Message{m_rank, tag, std::move(bytes)});
    }
    box.arrived.notify_all();
  }

  std::optional<Message> receive(double seconds) override {
    Mailboxes::Box& box = m_boxes->boxes[static_cast<std::size_t>(m_rank)];
    std::unique_lock lock(box.mutex);
    const auto wait = std::chrono::duration<double>(seconds);
    box.arrived.wait_for(lock, wait, [&] { return !box.messages.empty(); });
    if (box.messages.empty() || m_silent.load()) return std::nullopt;
    Message m = std::move(box.messages.front());
    box.messages.pop_front();
    return m;
  }

  void flush(double) override {}

  void make_silent() { m_silent.store(true); }

 private:
  std::shared_ptr<Mailboxes> m_boxes;
  int m_rank;
  std::atomic<bool> m_silent{false};
};

}  // namespace

std::vector<std::unique_ptr<Channel>> make_local_channels(int size) {
  auto boxes = std::make_shared<Mailboxes>(size);
  std::vector<std::unique_ptr<Channel>> out;
  for (int r = 0; r < size; ++r) out.push_back(std::make_unique<LocalChannel>(boxes, r));
  return out;
}

void silence(Channel& channel) { dynamic_cast<LocalChannel&>(channel).make_silent(); }

}  // namespace raylab::dist
