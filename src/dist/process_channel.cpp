#include "raylab/dist/process_channel.h"

#include "raylab/dist/launcher.h"
#include "raylab/dist/local_channel.h"

namespace raylab::dist {

ProcessChannel::ProcessChannel() {
  if (launched_by_mpi()) {
    require_mpi_build();
    m_session.emplace();
    m_channel = &m_session->channel();
  } else {
    m_local = make_local_channels(1);
    m_channel = m_local[0].get();
  }
}

std::string ProcessChannel::host() const { return m_session ? m_session->host() : "local"; }

}  // namespace raylab::dist
