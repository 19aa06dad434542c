//! Small fixed-capacity caches of closed mechanism loops (ankle slider-cranks, knee screws),
//! so that a loop is solved once per drive and kinematics pass and its solution is shared by
//! the drive's parts and by the drive-coordinate rows ([`crate::Data::coupled_spin_row`]).
//!
//! Entries are keyed by the drive's geometry and the exact input values `(q_in, qd_in)`, so a
//! lookup never returns a stale solution: a hit is bit-for-bit the loop at those inputs.

use std::sync::atomic::{AtomicU64, Ordering};

/// A fresh construction identity for a validated drive: copies share it and a drive's
/// geometry never changes after validation, so equal ids imply equal geometry (a cheap cache
/// key; equal geometry with different ids only costs a cache miss).
pub fn instance_id() -> u64 {
    static NEXT: AtomicU64 = AtomicU64::new(0);
    NEXT.fetch_add(1, Ordering::Relaxed)
}

/// Closed loops kept per mechanism type (Lola: four ankle slider-cranks, two knee drives).
pub const LOOP_SLOTS: usize = 4;

/// Round-robin store of `(key, closed loop)` pairs; lookups try the most recent entry first.
/// Loops are solved into their slot in place ([`Self::store_with`]): a closed loop is about 20
/// floats, and moving one into the store would be a `memmove` call per closure.
#[derive(Debug, Clone, Copy)]
pub struct LoopSlots<K: Copy, L: Copy> {
    keys: [Option<K>; LOOP_SLOTS],
    values: [L; LOOP_SLOTS],
    last: usize,
}

impl<K: Copy, L: Copy + Default> Default for LoopSlots<K, L> {
    fn default() -> Self {
        Self {
            keys: [None; LOOP_SLOTS],
            values: [L::default(); LOOP_SLOTS],
            last: 0,
        }
    }
}

impl<K: Copy, L: Copy> LoopSlots<K, L> {
    /// The newest entry whose key satisfies `hit`.
    #[inline]
    pub fn find(&self, hit: impl Fn(&K) -> bool) -> Option<&L> {
        self.position(hit).map(|i| &self.values[i])
    }

    /// Slot of the newest entry whose key satisfies `hit` (read it with [`Self::value`]; no
    /// borrow is held, so a miss can store into `self`).
    #[inline(always)]
    pub fn position(&self, hit: impl Fn(&K) -> bool) -> Option<usize> {
        let mut i = self.last % LOOP_SLOTS;
        for _ in 0..LOOP_SLOTS {
            if let Some(key) = &self.keys[i] {
                if hit(key) {
                    return Some(i);
                }
            }
            i = (i + LOOP_SLOTS - 1) % LOOP_SLOTS;
        }
        None
    }

    /// The value in slot `i` (from [`Self::position`]).
    #[inline]
    pub fn value(&self, i: usize) -> &L {
        &self.values[i % LOOP_SLOTS]
    }

    /// Solves a loop into the oldest slot (`solve` writes the value in place) and keys it
    /// `key`; returns the stored value. On an error the slot is left empty.
    #[inline]
    pub fn store_with<E>(
        &mut self,
        key: K,
        solve: impl FnOnce(&mut L) -> Result<(), E>,
    ) -> Result<&L, E> {
        let i = (self.last + 1) % LOOP_SLOTS;
        self.keys[i] = None;
        solve(&mut self.values[i])?;
        self.keys[i] = Some(key);
        self.last = i;
        Ok(&self.values[i])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Stores `value` under `key` (infallible solve).
    fn store(s: &mut LoopSlots<u32, u32>, key: u32, value: u32) {
        let stored = s.store_with(key, |v| {
            *v = value;
            Ok::<(), ()>(())
        });
        assert_eq!(stored, Ok(&value));
    }

    /// Newest match wins, the oldest entry is evicted first, misses return `None`.
    #[test]
    fn round_robin_lookup_and_eviction() {
        let mut s = LoopSlots::<u32, u32>::default();
        assert!(s.find(|_| true).is_none());
        for k in 0..LOOP_SLOTS as u32 {
            store(&mut s, k % 2, k);
        }
        assert_eq!(s.find(|&k| k == 0), Some(&2));
        assert_eq!(s.find(|&k| k == 1), Some(&3));
        store(&mut s, 7, 9);
        store(&mut s, 8, 10);
        store(&mut s, 9, 11);
        assert_eq!(s.find(|&k| k == 0), None);
        assert_eq!(s.find(|&k| k == 1), Some(&3));
        assert_eq!(s.find(|&k| k == 7), Some(&9));
    }

    /// A failed solve stores nothing: its slot (the oldest) is emptied, even if partly
    /// written, and the newest entry stays the newest.
    #[test]
    fn failed_solve_leaves_no_entry() {
        let mut s = LoopSlots::<u32, u32>::default();
        for k in 0..LOOP_SLOTS as u32 {
            store(&mut s, k, 10 + k);
        }
        let failed = s.store_with(99, |v| {
            *v = 123;
            Err("no root")
        });
        assert_eq!(failed, Err("no root"));
        assert!(s.find(|&k| k == 99).is_none());
        assert!(
            s.find(|&k| k == 0).is_none(),
            "the oldest slot was the one emptied"
        );
        assert_eq!(s.find(|_| true), Some(&13));
        store(&mut s, 5, 15);
        assert_eq!(s.find(|_| true), Some(&15));
    }
}
