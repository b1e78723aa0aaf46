#pragma once
// Mailboxing (Amanatides & Woo 1987) for structures that reference one primitive from several
// cells (the uniform grid, the octree): each ray gets an id, and a primitive is tested only when
// its mailbox does not already hold that id. Shared flags would race between threads, so every
// thread keeps its own stamps, found through a thread-local table keyed by the structure.
// Internal to src/accel.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace raylab {

/// The mailboxes of one structure: `size` slots, indexed by the structure's own dense reference
/// numbers (0 .. size - 1). Thread-safe: each thread stamps its own copy.
class Mailboxes {
 public:
  /// One ray's view of the calling thread's mailboxes.
  class RayStamp {
   public:
    /// True the first time `index` is seen by this ray (and records it); false afterwards.
    bool first_visit(std::uint32_t index) {
      if (m_stamps[index] == m_ray_id) return false;
      m_stamps[index] = m_ray_id;
      return true;
    }

   private:
    friend class Mailboxes;
    RayStamp(std::uint32_t* stamps, std::uint32_t ray_id) : m_stamps(stamps), m_ray_id(ray_id) {}
    std::uint32_t* m_stamps;
    std::uint32_t m_ray_id;
  };

  /// Mailboxes for `size` references.
  explicit Mailboxes(std::uint32_t size) : m_size(size), m_uid(next_uid()), m_alive(std::make_shared<char>(0)) {}
  Mailboxes(const Mailboxes&) = delete;
  Mailboxes& operator=(const Mailboxes&) = delete;

  /// Starts a new ray on the calling thread: a fresh ray id, so every slot reads "not seen".
  RayStamp begin_ray() const {
    Slot& slot = slot_for_this_thread();
    if (++slot.ray_id == 0) {  // ids wrapped around after 2^32 rays: clear and start over
      std::fill(slot.stamps.begin(), slot.stamps.end(), 0u);
      slot.ray_id = 1;
    }
    return RayStamp(slot.stamps.data(), slot.ray_id);
  }

  /// Bytes one thread's copy takes.
  std::size_t bytes_per_thread() const { return std::size_t(m_size) * sizeof(std::uint32_t); }

 private:
  struct Slot {
    std::vector<std::uint32_t> stamps;
    std::uint32_t ray_id = 0;
    std::weak_ptr<char> owner;  // expires with the structure, so the slot can be reclaimed
  };
  struct ThreadTable {
    std::unordered_map<std::uint64_t, Slot> slots;
    std::uint64_t last_uid = 0;  // one-entry cache in front of the table
    Slot* last_slot = nullptr;
  };

  static std::uint64_t next_uid() {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
  }

  Slot& slot_for_this_thread() const {
    thread_local ThreadTable table;
    if (table.last_uid == m_uid) return *table.last_slot;
    auto it = table.slots.find(m_uid);
    if (it == table.slots.end()) {
      // A new structure on this thread: first drop the slots of structures that are gone.
      std::erase_if(table.slots, [](const auto& entry) { return entry.second.owner.expired(); });
      it = table.slots.emplace(m_uid, Slot{std::vector<std::uint32_t>(m_size, 0u), 0u, m_alive}).first;
    }
    table.last_uid = m_uid;
    table.last_slot = &it->second;
    return it->second;
  }

  std::uint32_t m_size;
  std::uint64_t m_uid;            // never reused, unlike addresses
  std::shared_ptr<char> m_alive;  // its weak copies tell threads when this structure is gone
};

}  // namespace raylab
