//! The ancestors of every velocity coordinate in the DoF parent array `lambda` (thesis
//! 2.10.1), nearest first, in one flat list: the sparsity pattern of the mass matrix that the
//! reverse `L^T L` factorisation works on, walked as slices instead of parent chains.

/// Ancestor lists of the velocity coordinates, nearest first.
#[derive(Debug, Clone, Default)]
pub(crate) struct DofAncestors {
    /// `list[start[k]..start[k + 1]]` are the ancestors of coordinate `k`.
    start: Vec<usize>,
    list: Vec<usize>,
}

impl DofAncestors {
    /// The lists of the parent array `lambda` (`lambda[k] < k` where given).
    pub(crate) fn new(lambda: &[Option<usize>]) -> Self {
        let mut out = Self {
            start: Vec::with_capacity(lambda.len() + 1),
            list: Vec::new(),
        };
        for k in 0..lambda.len() {
            out.start.push(out.list.len());
            let mut i = lambda[k];
            while let Some(ii) = i {
                out.list.push(ii);
                i = lambda[ii];
            }
        }
        out.start.push(out.list.len());
        out
    }

    /// The ancestors of coordinate `k`, nearest first (those of an ancestor are a suffix).
    #[inline]
    pub(crate) fn of(&self, k: usize) -> &[usize] {
        &self.list[self.start[k]..self.start[k + 1]]
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
}
