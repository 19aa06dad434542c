//! The Dormand-Prince 5(4) tableau (Dormand & Prince 1980) and the coefficients of its free
//! fourth-order continuous extension (Hairer, Norsett & Wanner, Solving ODEs I, II.6).

/// Nodes `c_2..c_7`.
pub(crate) const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];

/// Lower-triangular coefficients `a_ij` (row `i` = stage `i + 1`).
pub(crate) const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    B6,
];

/// Fifth-order weights (equal to the last row of `A`, FSAL; `b_7 = 0`).
const B6: [f64; 6] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
];

/// Fifth-order weights of all seven stages.
pub(crate) const B: [f64; 7] = [B6[0], B6[1], B6[2], B6[3], B6[4], B6[5], 0.0];

/// Embedded fourth-order weights.
pub(crate) const BHAT: [f64; 7] = [
    5179.0 / 57600.0,
    0.0,
    7571.0 / 16695.0,
    393.0 / 640.0,
    -92097.0 / 339200.0,
    187.0 / 2100.0,
    1.0 / 40.0,
];

/// Error weights `b_i - bhat_i`.
pub(crate) const E: [f64; 7] = [
    B[0] - BHAT[0],
    B[1] - BHAT[1],
    B[2] - BHAT[2],
    B[3] - BHAT[3],
    B[4] - BHAT[4],
    B[5] - BHAT[5],
    B[6] - BHAT[6],
];

/// Coefficients `d_i` of the fourth-order continuous extension (Hairer, Norsett & Wanner).
pub(crate) const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// The Dormand-Prince tableau, exposed for order-condition tests.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tableau {
    /// Nodes `c_i`.
    pub c: [f64; 7],
    /// Coefficients `a_ij`, row `i` for stage `i`.
    pub a: [[f64; 6]; 7],
    /// Fifth-order weights.
    pub b: [f64; 7],
    /// Embedded fourth-order weights.
    pub bhat: [f64; 7],
    /// Dense-output coefficients `d_i`.
    pub d: [f64; 7],
}

/// The Dormand-Prince 5(4) tableau used by the integrator.
pub const TABLEAU: Tableau = Tableau {
    c: C,
    a: A,
    b: B,
    bhat: BHAT,
    d: D,
};
