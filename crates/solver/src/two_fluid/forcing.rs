//! What acts on the flow from outside the equations' own terms, set by a run before or
//! during it: gravity and its schedule, a bent floor's field (docs/model.md §9), gas let in
//! through walls, and the gates that close u faces (docs/model.md §9.2).

use runout_mesh::Sides;

use super::{TwoFluid, TwoFluidError};
use crate::bent_floor::BentFloor;
use crate::SideBc;

impl TwoFluid {
    /// Gas enters through the whole of the wall sides given, at this velocity normal to the
    /// side into the domain [m s⁻¹] ([`TwoFluid::set_gas_inflow_faces`] with one velocity on
    /// every face of a side). Outlet sides must get 0.
    pub fn set_gas_inflow(&mut self, inflow: Sides<f64>) -> Result<(), TwoFluidError> {
        let (nx, ny) = (self.model.grid.nx(), self.model.grid.ny());
        let faces = Sides::from_fn(|side| {
            let n = if side.is_horizontal() { nx } else { ny };
            let v = *inflow.get(side);
            if v == 0.0 {
                Vec::new()
            } else {
                vec![v; n]
            }
        });
        self.set_gas_inflow_faces(faces)
    }

    /// Gas enters through wall faces (a distributor plate, a porous wall, a vent): on each
    /// side, the velocity normal to the side into the domain on each face along it [m s⁻¹]
    /// (nx faces on the floor and top, ny on the west and east sides; an empty list for
    /// none). The gas's normal velocity on those faces is fixed at it and its face εg is 1
    /// where it is not 0, as MFIX's mass inlet with BC_EP_G = 1; the solids still see the
    /// wall. A run sets the faces from the case's `gas_inlets` before every step. Refused: a
    /// list of another length, a value that is not finite, gas let in through an outlet.
    pub fn set_gas_inflow_faces(&mut self, faces: Sides<Vec<f64>>) -> Result<(), TwoFluidError> {
        let (nx, ny) = (self.model.grid.nx(), self.model.grid.ny());
        for (side, velocities) in faces.iter() {
            let n = if side.is_horizontal() { nx } else { ny };
            if !velocities.is_empty() && velocities.len() != n {
                return Err(TwoFluidError::Shape(format!(
                    "gas inflow on the {side:?} side: {} velocities for {n} faces",
                    velocities.len()
                )));
            }
            if let Some(v) = velocities.iter().find(|v| !v.is_finite()) {
                return Err(TwoFluidError::Shape(format!(
                    "gas inflow on the {side:?} side: {v} m/s"
                )));
            }
            let open = velocities.iter().any(|&v| v != 0.0);
            if open && !matches!(self.model.gas_walls.get(side), SideBc::Wall(_)) {
                return Err(TwoFluidError::InflowOnOutlet(format!("{side:?}")));
            }
        }
        self.model.gas_inflow = faces;
        Ok(())
    }

    /// Sets gravity (a schedule may tilt it during a run).
    pub fn set_gravity(&mut self, gravity: (f64, f64)) {
        self.model.gravity = gravity;
    }

    /// Sets a bent floor (docs/model.md §9), whose field then replaces the uniform gravity,
    /// or `None` for a plane floor. A run sets it when the tilted gravity acts; a checkpoint
    /// does not hold it (the case does).
    pub fn set_bent_floor(&mut self, floor: Option<BentFloor>) {
        self.model.bent_floor = floor;
    }

    /// Closes the u faces flagged in `faces` ((nx + 1) × ny, row by row; empty for none) to
    /// the gas and every solids phase, as a gate across the flow does (`gates` of a case,
    /// issue 57 item 2): their rows hold u = 0 with no pressure or volume-fraction correction
    /// (d = e = 0), as a wall's normal faces do, and they do not count in the momentum
    /// residual. The gate holds only the normal velocity: it exerts no tangential stress on
    /// the v nodes beside it, and granular heat conducts across it. A run sets the faces from
    /// the case's gates before every step.
    pub fn set_gate_faces(&mut self, faces: Vec<bool>) -> Result<(), TwoFluidError> {
        let g = &self.model.grid;
        let expected = (g.nx() + 1) * g.ny();
        if !faces.is_empty() && faces.len() != expected {
            return Err(TwoFluidError::Shape(format!(
                "gate faces: {} flags for {expected} u faces",
                faces.len()
            )));
        }
        self.model.gate_faces = faces;
        Ok(())
    }

    /// The bent floor, if one acts.
    pub fn bent_floor(&self) -> Option<&BentFloor> {
        self.model.bent_floor.as_ref()
    }

    /// Gravity (g_x, g_y) [m s⁻²].
    pub fn gravity(&self) -> (f64, f64) {
        self.model.gravity
    }
}
