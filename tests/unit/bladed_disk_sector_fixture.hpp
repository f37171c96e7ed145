// A small bladed-disk sector (hex8, bore clamped) with its free system and paired cyclic faces:
// the model the cyclic unit tests share.
#pragma once
#include "articles/bladed_disk.hpp"
#include "assembly/free_system.hpp"
#include "cyclic/cyclic_boundary.hpp"
#include "model/model.hpp"

namespace bb {

inline Model sector_model(int sectors) {
  BladedDiskDimensions d;
  d.sectors = sectors;
  d.pitch = 0.05;
  d.disk_depth = 0.02;
  d.airfoil_length = 0.08;
  d.chord_divisions = 2;
  d.airfoil_divisions = 4;
  const BladedDiskSector s = bladed_disk_sector(d, ElementType::hex8);
  Model m;
  m.mesh = s.mesh;
  m.node_sets = s.sets;
  m.section = {2.0e11, 0.3, 7800.0, 0.0};
  m.constraints.push_back({"bore", {0, 1, 2}, 0.0});
  return m;
}

// A sector's model, its free system and its paired faces.
struct SectorSystem {
  explicit SectorSystem(int sectors)
      : model(sector_model(sectors)),
        system(assemble_free_system(model)),
        faces(pair_sector_faces(model.mesh, model.node_sets.at("cyclic_left"), model.node_sets.at("cyclic_right"),
                                sectors, 1e-9, "test")),
        cyclic(cyclic_dofs(model.mesh, system.dofs, faces, sectors)) {}
  Model model;
  FreeSystem system;
  SectorFaces faces;
  CyclicDofs cyclic;
};

}  // namespace bb
