// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/substrate.hpp"

namespace asp {

const char *substrate_name(SubstrateKind kind) {
  switch (kind) {
    case SubstrateKind::periodic: return "periodic half-space";
    case SubstrateKind::free: return "free half-space";
  }
  return "unknown";
}

}  // namespace asp
