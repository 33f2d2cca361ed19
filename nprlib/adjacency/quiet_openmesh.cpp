#include "adjacency/quiet_openmesh.h"

#include <OpenMesh/Core/System/omstream.hh>

namespace nq::npr::adjacency {

QuietOpenMesh::QuietOpenMesh()
    : err_was_enabled_(::omerr().is_enabled()),
      log_was_enabled_(::omlog().is_enabled()),
      out_was_enabled_(::omout().is_enabled()) {
    ::omerr().disable();
    ::omlog().disable();
    ::omout().disable();
}

QuietOpenMesh::~QuietOpenMesh() {
    if (err_was_enabled_) ::omerr().enable();
    if (log_was_enabled_) ::omlog().enable();
    if (out_was_enabled_) ::omout().enable();
}

}  // namespace nq::npr::adjacency
