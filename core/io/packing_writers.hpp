#pragma once
// Writers of a packing in the formats DEM users load: VTU (ParaView), YADE text, LAMMPS /
// LIGGGHTS data file (atom_style sphere), CSV, and the JSON run record with the particles.
//
// Conventions shared by every format:
// * Numbers are printed in the shortest decimal form that reads back to the same double
//   (std::to_chars), so files round-trip exactly through packing_readers.hpp; VTU stores the
//   raw doubles.
// * Ids: 0-based particle index in VTU ("id") and CSV; 1-based in LAMMPS (LAMMPS requires it).
// * 2D packings are written with z = 0.
// * Every write is atomic (atomic_file.hpp): on failure nothing is left behind and an
//   existing file is untouched; a missing output folder is an error, never created.
#include <string>

#include "core/geometry/packing.hpp"
#include "core/io/output_format.hpp"
#include "core/io/run_record.hpp"

namespace fp {

/// Writes `packing` to `path` in `format`. `record` supplies the LAMMPS box (record.bounds,
/// else the particles' bounding box grown by their radii) and density, and the whole JSON
/// record. Throws std::runtime_error naming the path on any failure.
template <int D>
void write_packing(OutputFormat format, const std::string& path, const Packing<D>& packing, const RunRecord& record);

}  // namespace fp
