// The equations a rank of a distributed model holds (docs/parallel.md "Vectors by rows"): the
// rows it owns in the solver's partition (the equations of its nodes, then the multipliers of its
// connectors) and, after them, the ghost equations its own elements read that other ranks own. The
// state, the forces and Newton's vectors of such a rank run over these local equations only; the
// plan's DofMap numbers them, so that elements, conditions and outputs find a node's local
// equations as they would its global ones, and a node the rank does not hold has none.
#pragma once

#include <string>
#include <vector>

namespace clinch {

struct AnalysisPlan;

struct EquationLayout {
  bool local = false;  // the plan's equations are this rank's (else the whole model's)
  int global_count = 0, global_node_equations = 0;
  int node_block = 1;  // of the global system (SparseMatrix::node_block)
  // Global numbers are the solver's: each rank's owned rows are consecutive, in rank order.
  int first_owned = 0;            // global number of local equation 0
  int owned = 0;                  // local equations [0, owned) are the owned rows, in global order
  std::vector<int> ghost_global;  // local equation owned + k is global ghost_global[k] (ascending)

  bool owns(int local_equation) const { return !local || local_equation < owned; }
  int global_of(int local_equation) const {
    if (!local) return local_equation;
    return local_equation < owned ? first_owned + local_equation
                                  : ghost_global[static_cast<std::size_t>(local_equation - owned)];
  }
  // −1 when this rank does not hold the equation.
  int local_of(int global_equation) const;
};

// Renumbers a rank's plan (build_analysis_plan with a share) over the equations of the rank:
// the nodes it owns (a node's owner is the rank whose share of the node equations holds its first
// equation, but the nodes a kinematic constraint ties together all go to the owner of the first
// of them), the multipliers of its connectors, then as ghosts the other nodes its connectors and
// springs touch and those the maps of its ghost dependent DOFs read. Sets `layout` and, for
// Newton's unknowns (the equations less the dependent ones), `solved_layout`; the dependent DOFs
// become those the rank holds.
void localize_equations(AnalysisPlan& plan, int rank, int ranks);

}  // namespace clinch
