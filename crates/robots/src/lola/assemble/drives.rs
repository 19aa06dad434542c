//! The drive parts of a joint: Harmonic Drive rotors, the knee's screw parts and the ankle's
//! slider-crank parts.

use super::*;

impl Assembler<'_> {
    /// Adds the drive parts of revolute joint `id`.
    pub(super) fn drive(
        &mut self,
        b: &BodyParams,
        id: BodyId,
        parent: Option<BodyId>,
        lower: f64,
        upper: f64,
    ) -> Result<(), LolaError> {
        let drive = b.drive.as_ref().map_or("none", |d| d.get_ref().as_str());
        let span = b.drive.as_ref().map_or(b.name.span(), |d| d.span());
        let need_parent = |field| {
            parent.ok_or_else(|| {
                self.loc
                    .invalid(span.clone(), field, "needs a parent".into())
            })
        };
        match drive {
            "none" => Ok(()),
            "harmonic" => {
                let parent = need_parent("drive")?;
                self.harmonic(b, id, parent)
            }
            "knee" => {
                let parent = need_parent("drive")?;
                self.knee(b, id, parent, lower, upper)
            }
            "ankle_flexion" => {
                let shank = need_parent("drive")?;
                self.require_axis(b, "y", "ankle flexion")?;
                self.ankles.insert(
                    id,
                    PendingAnkle {
                        shank,
                        cross: id,
                        center: Vector3::from(b.origin),
                        lower,
                        upper,
                    },
                );
                Ok(())
            }
            "ankle_adduction" => self.ankle(b, id, parent, lower, upper),
            other => Err(self.loc.invalid(
                span,
                "drive",
                format!("unknown drive `{other}` (harmonic, knee, ankle_flexion, ankle_adduction, none)"),
            )),
        }
    }

    fn require_axis(&self, b: &BodyParams, want: &str, what: &str) -> Result<(), LolaError> {
        match &b.axis {
            Some(a) if a.get_ref() == want => Ok(()),
            Some(a) => Err(self.loc.invalid(
                a.span(),
                "axis",
                format!("the {what} axis must be {want} (drive geometry)"),
            )),
            None => Err(self.loc.invalid(b.name.span(), "axis", "missing".into())),
        }
    }

    /// Harmonic Drive: a coupled rotor (rigid) or a motor body on its own joint (Type 3 elastic).
    fn harmonic(&mut self, b: &BodyParams, id: BodyId, parent: BodyId) -> Result<(), LolaError> {
        let Some(ratio) = &b.ratio else {
            return Err(self.loc.invalid(
                b.name.span(),
                "ratio",
                "missing for a harmonic drive".into(),
            ));
        };
        let axis = self.axis(b)?;
        let orientation =
            UnitQuaternion::rotation_between(&Vector3::z(), &axis).unwrap_or_default();
        let position = Vector3::from(b.origin);
        let inertia = box_inertia(&self.p.harmonic_rotor)?;
        let name = b.name.get_ref();
        if self.variant == LolaType::Type3 && b.elastic {
            let motor = self.builder.add_body(BodySpec {
                name: format!("{name}_motor"),
                joint_name: format!("{name}_motor"),
                parent: Some(parent),
                joint: JointModel::Revolute {
                    axis: Vector3::z_axis(),
                },
                placement: Isometry3::from_parts(Translation3::from(position), orientation),
                inertia,
            })?;
            self.motors
                .push((id, motor, *ratio.get_ref(), name.clone()));
            return Ok(());
        }
        let rotor = HarmonicDriveRotor::new(HarmonicDriveParams {
            ratio: *ratio.get_ref(),
            orientation,
            position,
            offset: 0.0,
        })
        .map_err(|e| self.loc.invalid(ratio.span(), "ratio", e.to_string()))?;
        self.part(
            format!("{name}_rotor"),
            parent,
            Isometry3::identity(),
            Mechanism::HarmonicDrive(rotor),
            vec![id],
            inertia,
        )
    }

    /// Knee roller screw: housing, nut and rotor in the thigh, input the knee angle.
    fn knee(
        &mut self,
        b: &BodyParams,
        id: BodyId,
        thigh: BodyId,
        lower: f64,
        upper: f64,
    ) -> Result<(), LolaError> {
        self.require_axis(b, "y", "knee")?;
        let k = &self.p.knee;
        let drive = KneeDrive::new(KneeDriveParams {
            lead: k.lead,
            q_min: lower,
            q_max: upper,
            q_ref: 0.0f64.clamp(lower, upper),
            ..KneeDriveParams::default()
        })?;
        // Knee frame: z = knee axis (+y), y up along the thigh, x = y x z (= -x).
        let rot = Rotation3::from_basis_unchecked(&[-Vector3::x(), Vector3::z(), Vector3::y()]);
        let place = Isometry3::from_parts(
            Translation3::new(b.origin[0], b.origin[1], b.origin[2]),
            UnitQuaternion::from_rotation_matrix(&rot),
        );
        let name = b.name.get_ref().clone();
        for (part, tag, params) in [
            (KneePart::Housing, "screw_housing", &k.housing),
            (KneePart::Nut, "screw_nut", &k.nut),
            (KneePart::Rotor, "screw_rotor", &k.rotor),
        ] {
            let inertia = box_inertia(params)?;
            let mech = Mechanism::Knee(drive.part(part));
            self.part(
                format!("{name}_{tag}"),
                thigh,
                place,
                mech,
                vec![id],
                inertia,
            )?;
        }
        Ok(())
    }

    /// Ankle: two slider-cranks (nut, rotor, rod each) in the shank, inputs flexion, adduction.
    fn ankle(
        &mut self,
        b: &BodyParams,
        id: BodyId,
        parent: Option<BodyId>,
        lower: f64,
        upper: f64,
    ) -> Result<(), LolaError> {
        let span = b.drive.as_ref().map_or(b.name.span(), |d| d.span());
        let Some(pending) = parent.and_then(|p| self.ankles.remove(&p)) else {
            let reason = "ankle_adduction must be the child of an ankle_flexion body".into();
            return Err(self.loc.invalid(span, "drive", reason));
        };
        self.require_axis(b, "x", "ankle adduction")?;
        if b.origin != [0.0; 3] {
            let reason = "the ankle is a universal joint: origin must be [0, 0, 0]".into();
            return Err(self.loc.invalid(b.name.span(), "origin", reason));
        }
        let a = &self.p.ankle;
        let drive = AnkleDrive::new(AnkleDriveParams {
            ankle_center: pending.center,
            lead: a.lead,
            q_min: [pending.lower, lower],
            q_max: [pending.upper, upper],
            ..AnkleDriveParams::default()
        })?;
        let name = b.name.get_ref().clone();
        for act in 0..2 {
            for (part, tag, params) in [
                (AnklePart::Nut, "nut", &a.nut),
                (AnklePart::Rotor, "rotor", &a.rotor),
                (AnklePart::Rod, "rod", &a.rod),
            ] {
                let inertia = box_inertia(params)?;
                let mech = Mechanism::Ankle(drive.part(act, part)?);
                let inputs = vec![pending.cross, id];
                let part_name = format!("{name}_ankle_{tag}_{act}");
                self.part(
                    part_name,
                    pending.shank,
                    Isometry3::identity(),
                    mech,
                    inputs,
                    inertia,
                )?;
            }
        }
        Ok(())
    }

    /// Adds one coupled part.
    fn part(
        &mut self,
        name: String,
        parent: BodyId,
        placement: Isometry3<f64>,
        mechanism: Mechanism,
        inputs: Vec<BodyId>,
        inertia: RigidInertia,
    ) -> Result<(), LolaError> {
        let id = self.builder.add_body(BodySpec {
            joint_name: name.clone(),
            name: name.clone(),
            parent: Some(parent),
            joint: JointModel::Coupled { mechanism, inputs },
            placement,
            inertia,
        })?;
        self.ids.insert(name, id);
        Ok(())
    }
}
