/**
 * @file explicit_solver_state.cc
 * The state of ExplicitSolver: setting the displacement and velocity
 * (initial conditions, static solution, steady rolling), measuring it
 * (momentum, mean displacements) and its checkpoint. Compiled with -O3 like
 * the rest of the integrator (CMakeLists.txt).
 */
#include <deal.II/base/mpi.h>

#include <wheelrail/mesh/geometry.h>
#include <wheelrail/solver/explicit_solver.h>

#include <array>

namespace WheelRail
{
  void
  ExplicitSolver::set_displacement(const std::function<Tensor<1, dim>(const Point<dim> &)> &u_of_X,
                                   const types::material_id material)
  {
    interpolate(u_of_X, material, u);
    u.update_ghost_values();
    distribute(u);
    u0 = u;
    for (auto &p : prescribed)
      p.u_prev = u.local_element(p.index);
    w_current = false;
  }



  void
  ExplicitSolver::set_velocity(
    const std::function<Tensor<1, dim>(const Point<dim> &, const types::material_id)> &v_of_X)
  {
    for (unsigned int i = 0; i < node_points.size(); ++i)
      if (node_material[i] != numbers::invalid_material_id)
        v.local_element(i) = v_of_X(node_points[i], node_material[i])[node_component[i]];
    v.update_ghost_values();
    distribute(v);
    for (auto &p : prescribed)
      p.v_prev = v.local_element(p.index);
    w_current = false;
  }



  void
  ExplicitSolver::add_centrifugal_load(const Point<dim> &centre, const double omega)
  {
    nodal_update_prepared     = false;
    f_ext_without_centrifugal = f_ext;
    for (unsigned int k = 0; k < f_ext.locally_owned_size(); ++k)
      if (node_material[k] == Geometry::MaterialIds::wheel && node_component[k] != 1)
        f_ext.local_element(k) +=
          mass.local_element(k) * omega * omega * (node_points[k] - centre)[node_component[k]];
  }



  void
  ExplicitSolver::remove_centrifugal_load()
  {
    AssertThrow(f_ext_without_centrifugal.size() == f_ext.size(),
                ExcMessage("Internal error: no centrifugal load to remove."));
    nodal_update_prepared = false;
    f_ext                 = f_ext_without_centrifugal;
    f_ext_without_centrifugal.reinit(0);
  }



  void
  ExplicitSolver::set_rolling_velocity(const Tensor<1, dim> &V,
                                       const Point<dim>     &centre,
                                       const double          omega)
  {
    // volume-weighted nodal average of H = grad u: gradient[j] holds H_ij at
    // DoF (node, i)
    std::array<VectorType, dim> gradient;
    VectorType                  weight;
    nodal_gradient(u, gradient, weight);

    for (unsigned int k = 0; k < v.locally_owned_size(); ++k)
      {
        const unsigned int i = node_component[k];
        double             H[3];
        for (unsigned int j = 0; j < 3; ++j)
          H[j] = weight.local_element(k) > 0 ?
                   gradient[j].local_element(k) / weight.local_element(k) :
                   0.;
        if (node_material[k] == Geometry::MaterialIds::wheel)
          {
            const Tensor<1, dim> r    = node_points[k] - centre;
            const double         w[3] = {omega * r[2], 0., -omega * r[0]};
            v.local_element(k)        = V[i] + w[i] + H[0] * w[0] + H[1] * w[1] + H[2] * w[2];
          }
        else
          v.local_element(k) = -V[0] * H[0];
      }
    v.update_ghost_values();
    distribute(v);
    for (auto &p : prescribed)
      p.v_prev = v.local_element(p.index);
    w_current = false;
  }



  void
  ExplicitSolver::set_displacement(const VectorType &displacement)
  {
    for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
      u.local_element(i) = displacement.local_element(i);
    u.update_ghost_values();
    distribute(u);
    u0 = u;
    for (auto &p : prescribed)
      p.u_prev = u.local_element(p.index);
    w_current = false;
  }



  Tensor<1, dim>
  ExplicitSolver::momentum(const types::material_id material) const
  {
    double local[3] = {0, 0, 0};
    for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
      if (node_material[i] == material)
        local[node_component[i]] += mass.local_element(i) * v.local_element(i);
    double global[3];
    Utilities::MPI::sum(ArrayView<const double>(local, 3),
                        mpi_communicator,
                        ArrayView<double>(global, 3));
    return Tensor<1, dim>({global[0], global[1], global[2]});
  }



  Tensor<1, dim>
  ExplicitSolver::mean_displacement(const types::material_id material) const
  {
    double local[4] = {0, 0, 0, 0};
    for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
      if (node_material[i] == material)
        {
          local[node_component[i]] += u.local_element(i);
          if (node_component[i] == 0)
            local[3] += 1;
        }
    double global[4];
    Utilities::MPI::sum(ArrayView<const double>(local, 4),
                        mpi_communicator,
                        ArrayView<double>(global, 4));
    Tensor<1, dim> mean;
    for (unsigned int d = 0; d < dim; ++d)
      mean[d] = global[3] > 0 ? global[d] / global[3] : 0.;
    return mean;
  }



  template <class Archive>
  void
  ExplicitSolver::serialize(Archive &ar)
  {
    for (VectorType *x : {&u, &v, &f_ext, &u0})
      ar.array(x->begin(), x->locally_owned_size());
    ar.pod(t);
    ar.pod(dt);
    ar.pod(n_steps);
    ar.pod(damping_dissipation);
    ar.pod(boundary_work);
    nodal_damping.serialize(ar);
    std::vector<double> states;
    if (!Archive::is_loading)
      for (const auto &p : prescribed)
        {
          states.push_back(p.u_prev);
          states.push_back(p.v_prev);
        }
    ar.vector(states);
    if (Archive::is_loading)
      {
        AssertThrow(states.size() == 2 * prescribed.size(),
                    ExcMessage("The checkpoint does not fit this run (prescribed DoFs differ)."));
        for (unsigned int i = 0; i < prescribed.size(); ++i)
          {
            prescribed[i].u_prev = states[2 * i];
            prescribed[i].v_prev = states[2 * i + 1];
          }
        nodal_update_prepared = false;
        w_current             = false;
        for (VectorType *x : {&u, &v, &f_ext, &u0})
          x->update_ghost_values();
        distribute(u);
        distribute(v);
      }
  }



  template void
  ExplicitSolver::serialize(Checkpoint::Writer &);
  template void
  ExplicitSolver::serialize(Checkpoint::Reader &);



  Tensor<1, dim>
  ExplicitSolver::bore_displacement() const
  {
    double local[4] = {0, 0, 0, 0};
    for (const unsigned int i : bore_dofs)
      {
        const unsigned int d = node_component[i];
        local[d] += u.local_element(i);
        if (d == 0)
          local[3] += 1;
      }
    double global[4];
    Utilities::MPI::sum(ArrayView<const double>(local, 4),
                        mpi_communicator,
                        ArrayView<double>(global, 4));
    Tensor<1, dim> mean;
    if (global[3] > 0)
      for (unsigned int d = 0; d < dim; ++d)
        mean[d] = global[d] / global[3];
    return mean;
  }
} // namespace WheelRail
