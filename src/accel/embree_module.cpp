// The Embree module's entry point (embree_backend.h): the one symbol libraylab_embree exports.

#include "embree_backend.h"

/// Both entry points of the module (embree_backend.h, kEmbreeEntriesSymbol).
extern "C" __attribute__((visibility("default"))) const raylab::EmbreeEntries* raylab_embree_entries() {
  static const raylab::EmbreeEntries entries{raylab::make_embree_accelerator_here, raylab::make_embree_reference_here};
  return &entries;
}
