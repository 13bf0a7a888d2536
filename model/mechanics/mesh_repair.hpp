// Repairs of quadratic meshes that a mesher can leave: curved elements folded by placing their edge
// nodes on the true surface. Such an element has a negative Jacobian somewhere and would make K
// indefinite; moving its edge nodes back onto the chords makes it a valid straight element.
#pragma once

#include <cstddef>

#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics {

// Every element whose Jacobian determinant is not positive somewhere (corners and quadrature
// points, as check_tet10 looks) gets its six edge nodes moved to the midpoints of its corners;
// neighbours sharing those nodes become straighter along that edge, which never folds them.
// Repeats until no element is folded (at most a few passes). Returns how many elements were
// straightened; elements inverted at their corners cannot be repaired and are left for check_tet10
// to report.
std::size_t straighten_inverted_elements(TetMesh& mesh);

}  // namespace nibrig::model::mechanics
