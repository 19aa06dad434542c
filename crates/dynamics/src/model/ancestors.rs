//! The ancestors of every velocity coordinate in the DoF parent array `lambda` (thesis
//! 2.10.1), nearest first: the sparsity pattern of the mass matrix that the reverse `L^T L`
//! factorisation works on, walked as flat lists instead of parent chains, and as runs of
//! consecutive indices (a chain of one-DoF joints numbered in order is one run), so that the
//! factorisation's updates are contiguous slices.

use std::ops::Range;

/// Ancestor lists of the velocity coordinates, nearest first, and their runs.
#[derive(Debug, Clone, Default)]
pub(crate) struct DofAncestors {
    /// `list[start[k]..start[k + 1]]` are the ancestors of coordinate `k`.
    start: Vec<usize>,
    list: Vec<usize>,
    /// `runs[run_start[k]..run_start[k + 1]]` are the ancestors of `k` as maximal ranges of
    /// consecutive indices, nearest (highest) first.
    run_start: Vec<usize>,
    runs: Vec<Range<usize>>,
}

impl DofAncestors {
    /// The lists of the parent array `lambda` (`lambda[k] < k` where given).
    pub(crate) fn new(lambda: &[Option<usize>]) -> Self {
        let mut out = Self {
            start: Vec::with_capacity(lambda.len() + 1),
            run_start: Vec::with_capacity(lambda.len() + 1),
            ..Self::default()
        };
        for k in 0..lambda.len() {
            out.start.push(out.list.len());
            out.run_start.push(out.runs.len());
            let mut i = lambda[k];
            while let Some(ii) = i {
                out.list.push(ii);
                let own = out.runs.len() > out.run_start[k];
                match out.runs.last_mut() {
                    Some(r) if own && r.start == ii + 1 => r.start = ii,
                    _ => out.runs.push(ii..ii + 1),
                }
                i = lambda[ii];
            }
        }
        out.start.push(out.list.len());
        out.run_start.push(out.runs.len());
        out
    }

    /// The ancestors of coordinate `k`, nearest first (those of an ancestor are a suffix);
    /// the factorisation walks [`Self::runs_of`], the tests check the runs against this list.
    #[cfg_attr(not(test), allow(dead_code))]
    #[inline]
    pub(crate) fn of(&self, k: usize) -> &[usize] {
        &self.list[self.start[k]..self.start[k + 1]]
    }

    /// The ancestors of coordinate `k` as maximal runs of consecutive indices, nearest first
    /// (descending, disjoint; their union is [`Self::of`]).
    #[inline]
    pub(crate) fn runs_of(&self, k: usize) -> &[Range<usize>] {
        &self.runs[self.run_start[k]..self.run_start[k + 1]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_follow_the_parent_chains() {
        // 0 <- 1 <- 2, 0 <- 3, 4 alone
        let lambda = [None, Some(0), Some(1), Some(0), None];
        let a = DofAncestors::new(&lambda);
        let lists: Vec<&[usize]> = (0..5).map(|k| a.of(k)).collect();
        assert_eq!(lists, [&[][..], &[0], &[1, 0], &[0], &[]]);
    }

    #[test]
    fn runs_cover_the_lists() {
        // 0 <- 1 <- 2 <- 3, 1 <- 4 <- 5, 0 <- 6
        let lambda = [None, Some(0), Some(1), Some(2), Some(1), Some(4), Some(0)];
        let a = DofAncestors::new(&lambda);
        assert_eq!(a.runs_of(3), std::slice::from_ref(&(0..3)));
        assert_eq!(a.runs_of(5), &[4..5, 0..2]);
        assert_eq!(a.runs_of(6), std::slice::from_ref(&(0..1)));
        assert!(a.runs_of(0).is_empty());
        for k in 0..lambda.len() {
            let from_runs: Vec<usize> = a.runs_of(k).iter().flat_map(|r| r.clone().rev()).collect();
            assert_eq!(from_runs, a.of(k));
        }
    }
}
