// Internal to the kernel: the Arb ball behind kernel::Ball (for kernel sources only).
#pragma once
#include <arb.h>

#include "derivations/kernel/ball.hpp"

namespace dc::kernel {

struct Ball::Impl {
  arb_t v;
  Impl() { arb_init(v); }
  ~Impl() { arb_clear(v); }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
};

}  // namespace dc::kernel
