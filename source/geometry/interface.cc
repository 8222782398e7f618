/**
 * @file geometry/interface.cc
 * The registry of the geometry models, the defaults of GeometryModel, and
 * Geometry::build(), which makes the mesh from a model's parts.
 */

#include <deal.II/base/exceptions.h>

#include <deal.II/grid/tria.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/cell_estimate.h>
#include <wheelrail/mesh/geometry.h>

#include <string>
#include <utility>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    namespace GeometryModels
    {
      // each defined in source/geometry/NAME.cc
      GeometryModel::Factory      wheel_and_rail;
      GeometryModel::Declarations wheel_and_rail_declarations;
      GeometryModel::Factory      bar;
      GeometryModel::Factory      block_on_plate;
    } // namespace GeometryModels



    namespace
    {
      /** A geometry: its name (the value of Problem/Geometry), its factory,
       *  and the declaration of its own entries (nullptr: none). */
      struct Registration
      {
        const char                  *name;
        GeometryModel::Factory      *factory;
        GeometryModel::Declarations *declarations;
      };

      /** The registry: one line per geometry, in the order of the
       *  Selection of Problem/Geometry (the first is its default). */
      const Registration registry[] = {
        {"wheel and rail",
         &GeometryModels::wheel_and_rail,
         &GeometryModels::wheel_and_rail_declarations},
        {"bar", &GeometryModels::bar, nullptr},
        {"block on plate", &GeometryModels::block_on_plate, nullptr},
      };
    } // namespace



    void
    GeometryModel::declare_parameters(ParameterHandler &prm)
    {
      for (const Registration &entry : registry)
        if (entry.declarations != nullptr)
          entry.declarations(prm);
    }



    std::unique_ptr<GeometryModel>
    GeometryModel::create(const std::string        &name,
                          const GeometryParameters &parameters,
                          ParameterHandler         &prm)
    {
      for (const Registration &entry : registry)
        if (name == entry.name)
          {
            std::unique_ptr<GeometryModel> model = entry.factory(parameters, prm);
            model->model_name                    = name;
            return model;
          }
      AssertThrow(false, ExcMessage("Unknown geometry '" + name + "' (known: " + names() + ")."));
      return nullptr;
    }



    std::string
    GeometryModel::names()
    {
      std::string selection;
      for (const Registration &entry : registry)
        selection += (selection.empty() ? "" : "|") + std::string(entry.name);
      return selection;
    }



    GeometryModel::GeometryModel(const GeometryParameters &parameters)
      : p(parameters)
    {}



    const std::string &
    GeometryModel::name() const
    {
      return model_name;
    }



    const char *
    GeometryModel::body_name(const types::material_id material) const
    {
      for (const Body &body : bodies())
        if (body.material == material)
          return body.name;
      return "unknown body";
    }



    void
    GeometryModel::set_manifold_ids(Triangulation<dim> &) const
    {}



    void
    GeometryModel::attach_manifolds(parallel::distributed::Triangulation<dim> &) const
    {}



    void
    GeometryModel::refine(parallel::distributed::Triangulation<dim> &) const
    {}



    std::optional<ZoneCells>
    GeometryModel::zone_cells(const types::material_id,
                              const parallel::distributed::Triangulation<dim> &) const
    {
      return std::nullopt;
    }



    std::pair<double, double>
    GeometryModel::zone_span() const
    {
      return {-p.zone_half_width, p.zone_half_width};
    }



    bool
    GeometryModel::has_wheel() const
    {
      return false;
    }



    Point<dim>
    GeometryModel::wheel_centre() const
    {
      return Geometry::wheel_centre(p);
    }



    double
    GeometryModel::rolling_radius() const
    {
      return p.wheel_radius;
    }



    std::string
    GeometryModel::description() const
    {
      return {};
    }



    std::vector<RigidContact>
    GeometryModel::rigid_contacts() const
    {
      return {};
    }



    bool
    GeometryModel::has_profile_files() const
    {
      return false;
    }



    ContactRadii
    GeometryModel::contact_radii() const
    {
      AssertThrow(false,
                  ExcMessage("The geometry '" + name() +
                             "' has no wheel on a rail: no Hertz "
                             "contact radii."));
      return {0, 0};
    }



    std::optional<double>
    GeometryModel::profile_contact_angle() const
    {
      if (!has_profile_files())
        return std::nullopt;
      return rigid_contacts().front().contact_angle;
    }



    bool
    GeometryModel::is_block_on_plate() const
    {
      return false;
    }



    std::pair<types::material_id, Point<dim>>
    GeometryModel::rotating_body() const
    {
      return {MaterialIds::wheel, wheel_centre()};
    }



    void
    build(const GeometryModel &model, parallel::distributed::Triangulation<dim> &triangulation)
    {
      internal::check_coarse_cell_estimate(model.coarse_cell_estimate(),
                                           triangulation.get_communicator());
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      model.create_coarse_mesh(vertices, cells);

      // The bodies are separate coarse meshes in one triangulation:
      // vertices are not merged, so wheel and rail never share a node.
      Triangulation<dim> coarse;
      coarse.create_triangulation(vertices, cells, SubCellData());
      for (const auto &cell : coarse.active_cell_iterators())
        AssertThrow(cell->measure() > 0, ExcMessage("Internal error: inverted coarse cell."));
      model.set_boundary_ids(coarse);
      model.set_manifold_ids(coarse);

      triangulation.copy_triangulation(coarse);
      model.attach_manifolds(triangulation);
      model.refine(triangulation);
    }
  } // namespace Geometry
} // namespace WheelRail
