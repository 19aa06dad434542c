//! Joint-space weight matrix W of the weighted generalized inverse (thesis eq. (4.11)).
//!
//! W is never inverted densely: `solve_into` applies W^-1 to a vector. The diagonal plus
//! rank-one form W = D + u u^T (used by angular momentum minimisation, W = delta E + J_Lz^T
//! J_Lz, thesis 7.3) is inverted by the Sherman-Morrison formula (7.13)-(7.15):
//! W^-1 x = D^-1 x - (D^-1 u)(u^T D^-1 x) / (1 + u^T D^-1 u), which is well defined because
//! D > 0 implies 1 + u^T D^-1 u >= 1.

use crate::error::IkError;
use nalgebra::{DMatrix, DVector};

/// Joint-space weight W of the generalized inverse (4.11); applied only through W^-1 x.
#[derive(Debug, Clone, PartialEq)]
pub enum Weight {
    /// W = E.
    Identity,
    /// W = diag(d), d_i > 0.
    Diagonal(DVector<f64>),
    /// W = diag(d) + u u^T, inverted by Sherman-Morrison (7.13)-(7.15).
    DiagonalRankOne {
        /// Diagonal part d (all > 0).
        diag: DVector<f64>,
        /// Rank-one vector u.
        u: DVector<f64>,
    },
}

impl Weight {
    /// Diagonal-plus-rank-one weight W = delta E + u u^T of size n (7.13), u = 0 initially.
    pub fn rank_one(n: usize, delta: f64) -> Result<Self, IkError> {
        check_positive(delta, 0)?;
        Ok(Weight::DiagonalRankOne {
            diag: DVector::from_element(n, delta),
            u: DVector::zeros(n),
        })
    }

    /// In-place update of W = delta E + u u^T without allocation (u copied from `u_row`).
    pub fn set_rank_one(&mut self, delta: f64, u_row: &[f64]) -> Result<(), IkError> {
        check_positive(delta, 0)?;
        match self {
            Weight::DiagonalRankOne { diag, u } if u.len() == u_row.len() => {
                diag.fill(delta);
                u.as_mut_slice().copy_from_slice(u_row);
                Ok(())
            }
            Weight::DiagonalRankOne { u, .. } => Err(IkError::Dimension {
                what: "rank-one vector u",
                expected: u.len(),
                got: u_row.len(),
            }),
            _ => Err(IkError::InvalidParameter {
                name: "weight",
                reason: "set_rank_one needs a DiagonalRankOne weight",
            }),
        }
    }

    /// Checks that all diagonal entries are > 0 and finite and sizes agree with n.
    pub fn validate(&self, n: usize) -> Result<(), IkError> {
        let check_len = |what, len: usize| {
            if len == n {
                Ok(())
            } else {
                Err(IkError::Dimension {
                    what,
                    expected: n,
                    got: len,
                })
            }
        };
        match self {
            Weight::Identity => Ok(()),
            Weight::Diagonal(d) => {
                check_len("weight diagonal", d.len())?;
                d.iter()
                    .enumerate()
                    .try_for_each(|(i, &v)| check_positive(v, i))
            }
            Weight::DiagonalRankOne { diag, u } => {
                check_len("weight diagonal", diag.len())?;
                check_len("rank-one vector u", u.len())?;
                diag.iter()
                    .enumerate()
                    .try_for_each(|(i, &v)| check_positive(v, i))?;
                if u.iter().all(|v| v.is_finite()) {
                    Ok(())
                } else {
                    Err(IkError::NonFinite("rank-one vector u"))
                }
            }
        }
    }

    /// out = W^-1 x without forming W^-1.
    pub fn solve_into(&self, x: &DVector<f64>, out: &mut DVector<f64>) -> Result<(), IkError> {
        let n = x.len();
        if out.len() != n {
            return Err(IkError::Dimension {
                what: "W^-1 x output",
                expected: n,
                got: out.len(),
            });
        }
        self.validate(n)?;
        self.apply_inverse(x.as_slice(), out.as_mut_slice());
        if out.iter().all(|v| v.is_finite()) {
            Ok(())
        } else {
            Err(IkError::NonFinite("W^-1 x"))
        }
    }

    /// `out = W^-1 x` on slices of equal length n, without validation (the caller has
    /// called [`Self::validate`] for n).
    pub(crate) fn apply_inverse(&self, x: &[f64], out: &mut [f64]) {
        match self {
            Weight::Identity => out.copy_from_slice(x),
            Weight::Diagonal(d) => {
                for ((o, xi), di) in out.iter_mut().zip(x).zip(d.iter()) {
                    *o = xi / di;
                }
            }
            Weight::DiagonalRankOne { diag, u } => {
                // out = D^-1 x; s = u^T D^-1 x; c = 1 + u^T D^-1 u  (7.14)
                let (mut s, mut c) = (0.0, 1.0);
                for i in 0..x.len() {
                    out[i] = x[i] / diag[i];
                    s += u[i] * out[i];
                    c += u[i] * u[i] / diag[i];
                }
                let f = s / c;
                for i in 0..x.len() {
                    out[i] -= f * u[i] / diag[i];
                }
            }
        }
    }

    /// The parts of `W^-1 = D^-1 - (D^-1 u)(D^-1 u)^T / c` (7.14): fills `dinv` with `D^-1`
    /// and `du` with `D^-1 u` (both of length n) and returns `c = 1 + u^T D^-1 u`, or 0 when
    /// W has no rank-one part (then `du` is untouched). No validation.
    pub(crate) fn inverse_parts(&self, dinv: &mut [f64], du: &mut [f64]) -> f64 {
        match self {
            Weight::Identity => {
                dinv.fill(1.0);
                0.0
            }
            Weight::Diagonal(d) => {
                for (o, di) in dinv.iter_mut().zip(d.iter()) {
                    *o = 1.0 / di;
                }
                0.0
            }
            Weight::DiagonalRankOne { diag, u } => {
                let mut c = 1.0;
                for (((o, e), di), ui) in dinv
                    .iter_mut()
                    .zip(du.iter_mut())
                    .zip(diag.iter())
                    .zip(u.iter())
                {
                    *o = 1.0 / di;
                    *e = ui * *o;
                    c += ui * *e;
                }
                c
            }
        }
    }

    /// Dense W (tests and diagnostics only).
    pub fn to_dense(&self, n: usize) -> DMatrix<f64> {
        match self {
            Weight::Identity => DMatrix::identity(n, n),
            Weight::Diagonal(d) => DMatrix::from_diagonal(d),
            Weight::DiagonalRankOne { diag, u } => DMatrix::from_diagonal(diag) + u * u.transpose(),
        }
    }
}

fn check_positive(v: f64, index: usize) -> Result<(), IkError> {
    if v > 0.0 && v.is_finite() {
        Ok(())
    } else {
        Err(IkError::NonPositiveWeight { index, value: v })
    }
}
