// SPDX-License-Identifier: MIT
#pragma once
// The errors render throws, GL-free, so that every part of render (text, drawing, the GL and
// vector painters) and the program can name them without including the Renderer or GL.
#include "core/error.hpp"

namespace collide::render {

// No GL context, a GL limit exceeded, a shader or vector surface that fails: a runtime failure
// (exit 1).
class RenderError : public core::RuntimeError {
 public:
  using core::RuntimeError::RuntimeError;
};

// A font file that cannot be used (missing, unreadable, not a scalable font): bad input, exit 2.
class FontError : public core::InputError {
 public:
  using core::InputError::InputError;
};

}  // namespace collide::render
