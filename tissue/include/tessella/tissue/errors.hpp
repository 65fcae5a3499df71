// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Error types. Library code never prints or exits: it throws one of these,
// with a message that names the element ids and values involved.

#include <stdexcept>
#include <string>

#include "tessella/tissue/handles.hpp"

namespace tessella {

/// Base of every error Tessella throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An edit or a build would break the complex (bad loop, wrong incidence).
/// The complex is left exactly as it was before the call.
class TopologyError : public Error {
 public:
  TopologyError(const std::string& what, ElementId element = {})
      : Error(what), element_(element) {}
  ElementId element() const { return element_; }

 private:
  ElementId element_;
};

/// Degenerate or invalid geometry (a plane missing a cell, a sliver, an
/// inverted cell). The complex is left exactly as it was before the call.
class GeometryError : public Error {
 public:
  GeometryError(const std::string& what, ElementId element = {})
      : Error(what), element_(element) {}
  ElementId element() const { return element_; }

 private:
  ElementId element_;
};

/// Bad user input (parameters, files).
class InputError : public Error {
 public:
  using Error::Error;
};

}  // namespace tessella
