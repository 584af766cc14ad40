//! Simulation data of one model, owned.

use super::{Error, Model, ObjKind};
use crate::abi::mjData;
use crate::abi::owned::DataBox;
use crate::abi::view::{self, DataRef, EngineError};
use crate::engine::{forward, integrate, inverse, jacobian, support};
use crate::math::quat::mat2quat;
use crate::runtime::{capture_errors, guard::catch};
use nalgebra::{
    DMatrix, DMatrixView, Isometry3, Quaternion, Translation3, UnitQuaternion, Vector3,
};

/// The simulation state and results of one [`Model`] (`mjData`), freed on drop.
///
/// `Send` (move it to another thread with its model shared), not `Sync`.
///
/// ```
/// let model = mujoco::Model::from_xml("models/arm3.xml")?;
/// let mut data = model.make_data()?;
/// data.reset_keyframe_named("home")?;
/// assert_eq!(data.qpos(), &[0.5, -1.0, 0.8]);
/// data.forward()?;
/// let ee = model.require_id(mujoco::ObjKind::Site, "ee")?;
/// let jac = data.jac_site(ee)?;
/// assert_eq!(jac.translation.shape(), (3, 3));
/// let mass = data.full_mass_matrix();
/// assert_eq!(mass, mass.transpose());
/// # Ok::<(), mujoco::Error>(())
/// ```
pub struct Data<'m> {
    model: &'m Model,
    raw: DataBox,
}

/// A Jacobian: 3×nv translational and rotational parts (`jacp`, `jacr`).
#[derive(Debug, Clone, PartialEq)]
pub struct Jacobian {
    pub translation: DMatrix<f64>,
    pub rotation: DMatrix<f64>,
}

macro_rules! arrays {
    ($($(#[$doc:meta])* $name:ident, $name_mut:ident;)*) => {
        $(
            $(#[$doc])*
            pub fn $name(&self) -> &[f64] {
                self.view().$name()
            }

            $(#[$doc])*
            pub fn $name_mut(&mut self) -> &mut [f64] {
                let mut v = self.raw.view(&self.model.raw);
                std::mem::take(&mut v.$name)
            }
        )*
    };
}

impl std::fmt::Debug for Data<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Data")
            .field("time", &self.time())
            .field("qpos", &self.qpos())
            .field("qvel", &self.qvel())
            .finish_non_exhaustive()
    }
}

impl<'m> Data<'m> {
    pub(crate) fn new(model: &'m Model, raw: DataBox) -> Self {
        Data { model, raw }
    }

    /// The model this data belongs to.
    pub fn model(&self) -> &'m Model {
        self.model
    }

    /// The `mjData` header: time, energy, warnings, diagnostics (read-only).
    pub fn raw(&self) -> &mjData {
        self.raw.raw()
    }

    /// Every `mjData` array by its 2.2.2 name, read-only (`data.arrays().xpos()`).
    pub fn arrays(&self) -> DataRef<'_> {
        self.view()
    }

    pub(crate) fn view(&self) -> DataRef<'_> {
        self.raw.view_ref(&self.model.raw)
    }

    /// Runs a core function: its error, an error raised meanwhile through `mju_error` (user
    /// callbacks), or a panic, comes back as [`Error::Engine`].
    fn run<R>(
        &mut self,
        name: &str,
        f: impl FnOnce(&view::Model, &mut view::Data) -> Result<R, EngineError>,
    ) -> Result<R, Error> {
        let m = &self.model.raw;
        let d = &mut self.raw;
        let (out, raised) = capture_errors(|| catch(name, || f(&m.view(), &mut d.view(m))));
        match (out, raised) {
            (_, Some(msg)) | (Ok(Err(EngineError(msg))), None) | (Err(msg), None) => {
                Err(Error::Engine(msg))
            }
            (Ok(Ok(r)), None) => Ok(r),
        }
    }

    /// Runs a core function on this data's views (unit tests of the engine).
    #[cfg(test)]
    pub(crate) fn with_core<R>(
        &mut self,
        f: impl FnOnce(&view::Model, &mut view::Data) -> Result<R, EngineError>,
    ) -> Result<R, Error> {
        self.run("test", f)
    }

    /// Advances the simulation one time step (`mj_step`).
    pub fn step(&mut self) -> Result<(), Error> {
        self.run("mj_step", forward::step)
    }

    /// The first half of a step, up to the controls (`mj_step1`).
    pub fn step1(&mut self) -> Result<(), Error> {
        self.run("mj_step1", forward::step1)
    }

    /// The second half of a step, from the controls on (`mj_step2`).
    pub fn step2(&mut self) -> Result<(), Error> {
        self.run("mj_step2", forward::step2)
    }

    /// Forward dynamics without integration (`mj_forward`): kinematics, forces, qacc.
    pub fn forward(&mut self) -> Result<(), Error> {
        self.run("mj_forward", forward::forward)
    }

    /// Inverse dynamics (`mj_inverse`): qfrc_inverse from qacc.
    pub fn inverse(&mut self) -> Result<(), Error> {
        self.run("mj_inverse", inverse::inverse)
    }

    /// Back to the model's initial state (`mj_resetData`).
    pub fn reset(&mut self) {
        support::reset_data(&self.model.raw.view(), &mut self.raw.view(&self.model.raw));
    }

    /// Reset, then state and controls from keyframe `key` (`mj_resetDataKeyframe`).
    pub fn reset_keyframe(&mut self, key: usize) -> Result<(), Error> {
        if key >= self.model.nkey() {
            return Err(Error::Invalid(format!("no keyframe {key}")));
        }
        let m = &self.model.raw;
        support::reset_data_keyframe(&m.view(), &mut self.raw.view(m), key as i32);
        Ok(())
    }

    /// Reset to the keyframe named `name`.
    pub fn reset_keyframe_named(&mut self, name: &str) -> Result<(), Error> {
        let key = self.model.require_id(ObjKind::Key, name)?;
        self.reset_keyframe(key)
    }

    /// Simulation time.
    pub fn time(&self) -> f64 {
        self.raw().time
    }

    pub fn set_time(&mut self, t: f64) {
        self.raw.view(&self.model.raw).raw.time = t;
    }

    arrays! {
        /// Joint positions (nq).
        qpos, qpos_mut;
        /// Joint velocities (nv).
        qvel, qvel_mut;
        /// Joint accelerations (nv).
        qacc, qacc_mut;
        /// Actuator controls (nu).
        ctrl, ctrl_mut;
        /// Actuator activations (na).
        act, act_mut;
        /// Applied generalized forces (nv).
        qfrc_applied, qfrc_applied_mut;
        /// Sensor outputs (nsensordata).
        sensordata, sensordata_mut;
    }

    /// Actuator forces (nu).
    pub fn actuator_force(&self) -> &[f64] {
        self.view().actuator_force()
    }

    /// Inverse dynamics result (nv).
    pub fn qfrc_inverse(&self) -> &[f64] {
        self.view().qfrc_inverse()
    }

    /// Body frame positions as the columns of a 3×nbody matrix.
    pub fn body_positions(&self) -> DMatrixView<'_, f64> {
        DMatrixView::from_slice(self.view().xpos(), 3, self.model.nbody())
    }

    /// Integrates `qvel` over `dt` into qpos, quaternions on their sphere (`mj_integratePos`).
    pub fn integrate_qpos(&mut self, qvel: &[f64], dt: f64) -> Result<(), Error> {
        if qvel.len() != self.model.nv() {
            return Err(Error::Invalid(format!(
                "qvel has {} values, the model nv = {}",
                qvel.len(),
                self.model.nv()
            )));
        }
        let m = &self.model.raw;
        let d = self.raw.view(m);
        integrate::integrate_pos(&m.view(), d.qpos, qvel, dt);
        Ok(())
    }

    fn check(&self, kind: ObjKind, id: usize, n: usize) -> Result<(), Error> {
        if id < n {
            Ok(())
        } else {
            Err(Error::Invalid(format!(
                "{} id {id} out of range",
                kind.label()
            )))
        }
    }

    /// Jacobian of a point attached to `body` (world coordinates), from the last forward
    /// kinematics (`mj_jac`).
    pub fn jac_point(&self, body: usize, point: &Vector3<f64>) -> Result<Jacobian, Error> {
        self.check(ObjKind::Body, body, self.model.nbody())?;
        let nv = self.model.nv();
        let (mut p, mut r) = (vec![0.0; 3 * nv], vec![0.0; 3 * nv]);
        let d = self.view();
        let point = [point.x, point.y, point.z];
        let mv = self.model.raw.view();
        catch("mj_jac", || {
            jacobian::jac(
                &mv,
                d.cdof(),
                d.subtree_com(),
                &point,
                body,
                Some(&mut p),
                Some(&mut r),
            )
        })
        .map_err(Error::Engine)?;
        Ok(Jacobian {
            translation: DMatrix::from_row_slice(3, nv, &p),
            rotation: DMatrix::from_row_slice(3, nv, &r),
        })
    }

    /// Jacobian of site `site` (`mj_jacSite`).
    pub fn jac_site(&self, site: usize) -> Result<Jacobian, Error> {
        self.check(ObjKind::Site, site, self.model.nsite())?;
        let body = self.model.raw.view().site_bodyid()[site] as usize;
        self.jac_point(body, &self.site_position(site)?)
    }

    /// Jacobian of the frame origin of `body` (`mj_jacBody`).
    pub fn jac_body(&self, body: usize) -> Result<Jacobian, Error> {
        self.check(ObjKind::Body, body, self.model.nbody())?;
        let p = &self.view().xpos()[3 * body..3 * body + 3];
        self.jac_point(body, &Vector3::new(p[0], p[1], p[2]))
    }

    /// Jacobian of the center of mass of `body` (`mj_jacBodyCom`).
    pub fn jac_body_com(&self, body: usize) -> Result<Jacobian, Error> {
        self.check(ObjKind::Body, body, self.model.nbody())?;
        let p = &self.view().xipos()[3 * body..3 * body + 3];
        self.jac_point(body, &Vector3::new(p[0], p[1], p[2]))
    }

    /// The dense nv×nv joint-space inertia matrix (`mj_fullM` of qM, from the last forward).
    pub fn full_mass_matrix(&self) -> DMatrix<f64> {
        let nv = self.model.nv();
        let mut dense = vec![0.0; nv * nv];
        jacobian::full_m(&self.model.raw.view(), &mut dense, self.view().qM());
        DMatrix::from_row_slice(nv, nv, &dense)
    }

    /// World position of site `site`.
    pub fn site_position(&self, site: usize) -> Result<Vector3<f64>, Error> {
        self.check(ObjKind::Site, site, self.model.nsite())?;
        Ok(Vector3::from_column_slice(
            &self.view().site_xpos()[3 * site..3 * site + 3],
        ))
    }

    /// World pose of site `site` (orientation from its rotation matrix, as mju_mat2Quat).
    pub fn site_pose(&self, site: usize) -> Result<Isometry3<f64>, Error> {
        let pos = self.site_position(site)?;
        let mut mat = [0.0; 9];
        mat.copy_from_slice(&self.view().site_xmat()[9 * site..9 * site + 9]);
        let q = mat2quat(&mat);
        Ok(pose(pos, q))
    }

    /// World pose of the frame of `body`.
    pub fn body_pose(&self, body: usize) -> Result<Isometry3<f64>, Error> {
        self.check(ObjKind::Body, body, self.model.nbody())?;
        let d = self.view();
        let pos = Vector3::from_column_slice(&d.xpos()[3 * body..3 * body + 3]);
        let mut q = [0.0; 4];
        q.copy_from_slice(&d.xquat()[4 * body..4 * body + 4]);
        Ok(pose(pos, q))
    }
}

/// A pose from a position and a MuJoCo quaternion (w, x, y, z), taken as unit.
fn pose(pos: Vector3<f64>, q: [f64; 4]) -> Isometry3<f64> {
    let rotation = UnitQuaternion::new_unchecked(Quaternion::new(q[0], q[1], q[2], q[3]));
    Isometry3::from_parts(Translation3::from(pos), rotation)
}
