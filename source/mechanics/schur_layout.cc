#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <levelsinter/mechanics/schur_layout.h>

namespace levelsinter
{
  void
  make_schur_layout(const TrilinosWrappers::BlockSparseMatrix &system,
                    const std::vector<IndexSet>               &owned,
                    const std::vector<IndexSet>               &relevant,
                    const AffineConstraints<double>           &constraints,
                    TrilinosWrappers::BlockSparseMatrix       &schur)
  {
    AssertDimension(owned.size(), 2);
    AssertDimension(relevant.size(), 2);
    const MPI_Comm comm = system.get_mpi_communicator();
    schur.reinit(2, 2);
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        if (i == 1 && j == 1)
          schur.block(i, j).reinit(system.block(i, j));
        else
          {
            DynamicSparsityPattern dsp(owned[i].size(),
                                       owned[j].size(),
                                       relevant[i]);
            // Block 0 starts at DoF 0: its indices are the DoFs'.
            if (i == 0 && j == 0)
              for (const auto k : relevant[0])
                if (constraints.is_constrained(k))
                  dsp.add(k, k);
            SparsityTools::distribute_sparsity_pattern(dsp,
                                                       owned[i],
                                                       comm,
                                                       relevant[i]);
            schur.block(i, j).reinit(owned[i], owned[j], dsp, comm);
          }
    schur.collect_sizes();
  }
} // namespace levelsinter
