// Gmsh keeps one global model and is not thread-safe: every use goes through a GmshSession, which
// holds a process-wide lock, initialises Gmsh quietly, collects its log so that failures can be
// reported in our own words, and finalises it again. It also turns Gmsh's current mesh into a
// TetMesh.
#pragma once

#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics {

class GmshSession {
 public:
  explicit GmshSession(const std::string& model_name);
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  // Gmsh's own error messages since the session began (Gmsh 4.8 reports many failures only in
  // its log, without throwing); empty when there were none.
  std::vector<std::string> errors() const;
  // Throws std::runtime_error("<what>: <Gmsh's first error>") when Gmsh logged an error.
  void throw_if_failed(const std::string& what) const;

 private:
  std::unique_lock<std::mutex> lock_;
};

// Runs `body`, which calls into Gmsh, and turns what Gmsh throws that is not a std::exception into
// std::runtime_error("<what>: Gmsh: ..."): Gmsh 4.8 throws a bare std::string from OpenCASCADE
// (addCylinder with a body_length of 1e3 ended the process in std::terminate). Every use of Gmsh
// goes through it.
template <class Body>
auto guard_gmsh(const std::string& what, Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const std::exception&) {
    throw;
  } catch (const std::string& message) {
    throw std::runtime_error(what + ": Gmsh: " + message);
  } catch (const char* message) {
    throw std::runtime_error(what + ": Gmsh: " + std::string(message != nullptr ? message : ""));
  } catch (...) {
    throw std::runtime_error(what + ": Gmsh failed with an error that is not a message");
  }
}

// Sets the element size (m) and second order, and meshes the current model in 3-D. Curved
// boundaries get their edge nodes on the true surface (isoparametric elements).
void generate_quadratic_tets(double max_size, double min_size);

// The current Gmsh mesh as a TetMesh: 10-node tetrahedra only (a first-order mesh is raised to
// second order first), nodes renumbered densely. A volume's region is the name of its physical
// group when it has one, otherwise `default_region`. Every named physical group of points, curves
// or surfaces becomes a node set of that name (how a .msh file marks its "clamp").
TetMesh tet_mesh_from_gmsh(const std::string& default_region);

}  // namespace nibrig::model::mechanics
