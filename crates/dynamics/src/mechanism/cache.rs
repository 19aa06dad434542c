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
#[derive(Debug, Clone, Copy)]
pub struct LoopSlots<K: Copy, L: Copy> {
    slots: [Option<(K, L)>; LOOP_SLOTS],
    last: usize,
}

impl<K: Copy, L: Copy> Default for LoopSlots<K, L> {
    fn default() -> Self {
        Self {
            slots: [None; LOOP_SLOTS],
            last: 0,
        }
    }
}

impl<K: Copy, L: Copy> LoopSlots<K, L> {
    /// The newest entry whose key satisfies `hit`.
    #[inline]
    pub fn find(&self, hit: impl Fn(&K) -> bool) -> Option<&L> {
        let mut i = self.last % LOOP_SLOTS;
        for _ in 0..LOOP_SLOTS {
            if let Some((key, l)) = &self.slots[i] {
                if hit(key) {
                    return Some(l);
                }
            }
            i = (i + LOOP_SLOTS - 1) % LOOP_SLOTS;
        }
        None
    }

    /// Stores an entry in place of the oldest one and returns the stored value.
    #[inline]
    pub fn store(&mut self, key: K, value: L) -> &L {
        self.last = (self.last + 1) % LOOP_SLOTS;
        &self.slots[self.last].insert((key, value)).1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Newest match wins, the oldest entry is evicted first, misses return `None`.
    #[test]
    fn round_robin_lookup_and_eviction() {
        let mut s = LoopSlots::<u32, u32>::default();
        assert!(s.find(|_| true).is_none());
        for k in 0..LOOP_SLOTS as u32 {
            s.store(k % 2, k);
        }
        assert_eq!(s.find(|&k| k == 0), Some(&2));
        assert_eq!(s.find(|&k| k == 1), Some(&3));
        s.store(7, 9);
        s.store(8, 10);
        s.store(9, 11);
        assert_eq!(s.find(|&k| k == 0), None);
        assert_eq!(s.find(|&k| k == 1), Some(&3));
        assert_eq!(s.find(|&k| k == 7), Some(&9));
    }
}
