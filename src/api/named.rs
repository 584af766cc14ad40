//! Handles on one named object of a [`Data`]: `data.joint("elbow")?.qpos()`.

use super::{Data, Error, Jacobian, ObjKind};
use crate::abi::mjtJoint;
use nalgebra::{Isometry3, Vector3};

/// A joint, read-only.
pub struct Joint<'a, 'm> {
    data: &'a Data<'m>,
    id: usize,
}

/// A joint, writable.
pub struct JointMut<'a, 'm> {
    data: &'a mut Data<'m>,
    id: usize,
}

/// An actuator, read-only.
pub struct Actuator<'a, 'm> {
    data: &'a Data<'m>,
    id: usize,
}

/// An actuator, writable (its control).
pub struct ActuatorMut<'a, 'm> {
    data: &'a mut Data<'m>,
    id: usize,
}

/// A sensor's output.
pub struct Sensor<'a, 'm> {
    data: &'a Data<'m>,
    id: usize,
}

/// A site's pose and Jacobian.
pub struct Site<'a, 'm> {
    data: &'a Data<'m>,
    id: usize,
}

/// A body's pose and Jacobians.
pub struct Body<'a, 'm> {
    data: &'a Data<'m>,
    id: usize,
}

/// (qpos address, qpos width, dof address, dof width) of joint `id`.
fn joint_span(data: &Data, id: usize) -> (usize, usize, usize, usize) {
    let m = data.model().raw.view();
    let (nq, nv) = match m.jnt_type()[id] {
        t if t == mjtJoint::mjJNT_FREE as i32 => (7, 6),
        t if t == mjtJoint::mjJNT_BALL as i32 => (4, 3),
        _ => (1, 1),
    };
    (
        m.jnt_qposadr()[id] as usize,
        nq,
        m.jnt_dofadr()[id] as usize,
        nv,
    )
}

impl<'m> Data<'m> {
    fn lookup(&self, kind: ObjKind, name: &str) -> Result<usize, Error> {
        self.model().require_id(kind, name)
    }

    /// The joint named `name`.
    pub fn joint(&self, name: &str) -> Result<Joint<'_, 'm>, Error> {
        let id = self.lookup(ObjKind::Joint, name)?;
        Ok(Joint { data: self, id })
    }

    /// The joint named `name`, writable.
    pub fn joint_mut(&mut self, name: &str) -> Result<JointMut<'_, 'm>, Error> {
        let id = self.lookup(ObjKind::Joint, name)?;
        Ok(JointMut { data: self, id })
    }

    /// The actuator named `name`.
    pub fn actuator(&self, name: &str) -> Result<Actuator<'_, 'm>, Error> {
        let id = self.lookup(ObjKind::Actuator, name)?;
        Ok(Actuator { data: self, id })
    }

    /// The actuator named `name`, writable.
    pub fn actuator_mut(&mut self, name: &str) -> Result<ActuatorMut<'_, 'm>, Error> {
        let id = self.lookup(ObjKind::Actuator, name)?;
        Ok(ActuatorMut { data: self, id })
    }

    /// The sensor named `name`.
    pub fn sensor(&self, name: &str) -> Result<Sensor<'_, 'm>, Error> {
        let id = self.lookup(ObjKind::Sensor, name)?;
        Ok(Sensor { data: self, id })
    }

    /// The site named `name`.
    pub fn site(&self, name: &str) -> Result<Site<'_, 'm>, Error> {
        let id = self.lookup(ObjKind::Site, name)?;
        Ok(Site { data: self, id })
    }

    /// The body named `name`.
    pub fn body(&self, name: &str) -> Result<Body<'_, 'm>, Error> {
        let id = self.lookup(ObjKind::Body, name)?;
        Ok(Body { data: self, id })
    }
}

impl Joint<'_, '_> {
    pub fn id(&self) -> usize {
        self.id
    }

    /// Its positions (1 for hinge and slide, 4 for ball, 7 for free joints).
    pub fn qpos(&self) -> &[f64] {
        let (a, n, _, _) = joint_span(self.data, self.id);
        &self.data.qpos()[a..a + n]
    }

    /// Its velocities (1, 3 or 6).
    pub fn qvel(&self) -> &[f64] {
        let (_, _, a, n) = joint_span(self.data, self.id);
        &self.data.qvel()[a..a + n]
    }
}

impl JointMut<'_, '_> {
    pub fn id(&self) -> usize {
        self.id
    }

    pub fn qpos(&self) -> &[f64] {
        let (a, n, _, _) = joint_span(self.data, self.id);
        &self.data.qpos()[a..a + n]
    }

    pub fn qvel(&self) -> &[f64] {
        let (_, _, a, n) = joint_span(self.data, self.id);
        &self.data.qvel()[a..a + n]
    }

    pub fn qpos_mut(&mut self) -> &mut [f64] {
        let (a, n, _, _) = joint_span(self.data, self.id);
        &mut self.data.qpos_mut()[a..a + n]
    }

    pub fn qvel_mut(&mut self) -> &mut [f64] {
        let (_, _, a, n) = joint_span(self.data, self.id);
        &mut self.data.qvel_mut()[a..a + n]
    }
}

impl Actuator<'_, '_> {
    pub fn id(&self) -> usize {
        self.id
    }

    pub fn ctrl(&self) -> f64 {
        self.data.ctrl()[self.id]
    }

    /// Its force (from the last forward dynamics).
    pub fn force(&self) -> f64 {
        self.data.actuator_force()[self.id]
    }
}

impl ActuatorMut<'_, '_> {
    pub fn id(&self) -> usize {
        self.id
    }

    pub fn ctrl(&self) -> f64 {
        self.data.ctrl()[self.id]
    }

    pub fn set_ctrl(&mut self, value: f64) {
        self.data.ctrl_mut()[self.id] = value;
    }
}

impl Sensor<'_, '_> {
    pub fn id(&self) -> usize {
        self.id
    }

    /// Its output values (sensor_dim of them, from the last forward dynamics).
    pub fn data(&self) -> &[f64] {
        let m = self.data.model().raw.view();
        let (a, n) = (
            m.sensor_adr()[self.id] as usize,
            m.sensor_dim()[self.id] as usize,
        );
        &self.data.sensordata()[a..a + n]
    }
}

impl Site<'_, '_> {
    pub fn id(&self) -> usize {
        self.id
    }

    pub fn position(&self) -> Vector3<f64> {
        // the id came from the model: in range
        self.data.site_position(self.id).unwrap_or_default()
    }

    pub fn pose(&self) -> Isometry3<f64> {
        self.data.site_pose(self.id).unwrap_or_default()
    }

    pub fn jacobian(&self) -> Result<Jacobian, Error> {
        self.data.jac_site(self.id)
    }
}

impl Body<'_, '_> {
    pub fn id(&self) -> usize {
        self.id
    }

    pub fn pose(&self) -> Isometry3<f64> {
        self.data.body_pose(self.id).unwrap_or_default()
    }

    /// Position of its center of mass.
    pub fn com(&self) -> Vector3<f64> {
        let p = &self.data.view().xipos()[3 * self.id..3 * self.id + 3];
        Vector3::new(p[0], p[1], p[2])
    }

    pub fn jacobian(&self) -> Result<Jacobian, Error> {
        self.data.jac_body(self.id)
    }

    pub fn jacobian_com(&self) -> Result<Jacobian, Error> {
        self.data.jac_body_com(self.id)
    }
}
