//! The model behind roughtui: Persson's elasto-plastic rough contact with the
//! size-dependent hardness of Swadener, George and Pharr, as combined by
//! Ciavarella (Lubricants 2024, 12(3), 83) into the plasticity index Ψ*.
//!
//! Pure and immutable: no I/O, no terminal. Inputs are validated once
//! ([`Params::new`]); everything else is a function of them. `docs/model.md` in the
//! project's shared folder states every formula; each public function's doc
//! gives its domain, units and accuracy.

pub mod areas;
mod dd;
pub mod indices;
pub mod measured;
pub mod params;
pub mod roughness;
pub mod scene;
pub mod slopes;
pub mod spectrum;
mod sweep;

pub use areas::{areas, closed_form_areas, exact_areas, AreaError, Areas};
pub use dd::Dd;
pub use indices::{psi_in_use, Indices, Surface};
pub use measured::{Dim, MomentTable, ProfileMoments, TableError};
pub use params::{Axis, ParamError, ParamValues, Params};
pub use roughness::{Roughness, RoughnessError};
pub use scene::{Curves, Scene, SceneSpec};
pub use slopes::{closed_form, exact, persson_elastic, slopes, Model, Regime, Slopes};
pub use spectrum::{Moments, Spectrum};
pub use sweep::{Sweep, SweepError};
