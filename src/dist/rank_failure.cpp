#include "raylab/dist/rank_failure.h"

#include "raylab/core/error.h"
#include "raylab/dist/distributed_render.h"

namespace raylab::dist {

int fail_outside_protocol(Channel& channel, const std::exception& e) {
  if (channel.rank() == 0) {
    call_off(channel);
    throw;  // the exception being handled: the program prints it and maps it to the exit code
  }
  report_failure(channel, e.what(), 30.0);
  if (dynamic_cast<const UsageError*>(&e) != nullptr) return 2;
  return dynamic_cast<const InputError*>(&e) != nullptr ? 1 : 3;
}

}  // namespace raylab::dist
