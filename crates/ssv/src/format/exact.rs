//! Arrays of exactly `N` entries in a model file. serde's `[T; N]` reads the first `N`
//! entries of a TOML array and the toml crate drops any further ones silently (a pair of three
//! segment names lost the third); [`Exact`] makes extra entries an error like missing ones.

use serde::de::{Deserialize, Deserializer, Error, IgnoredAny, SeqAccess, Visitor};
use serde::ser::{Serialize, SerializeTuple, Serializer};
use std::fmt;
use std::marker::PhantomData;

/// An array that must have exactly `N` entries.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Exact<T, const N: usize>(pub [T; N]);

impl<'de, T: Deserialize<'de>, const N: usize> Deserialize<'de> for Exact<T, N> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_seq(ExactVisitor::<T, N>(PhantomData))
    }
}

/// Reads `N` entries, then counts any further ones for the error.
struct ExactVisitor<T, const N: usize>(PhantomData<T>);

impl<'de, T: Deserialize<'de>, const N: usize> Visitor<'de> for ExactVisitor<T, N> {
    type Value = Exact<T, N>;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "an array of length {N}")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let mut items = Vec::with_capacity(N);
        while items.len() < N {
            match seq.next_element()? {
                Some(item) => items.push(item),
                None => return Err(A::Error::invalid_length(items.len(), &self)),
            }
        }
        let mut len = N;
        while seq.next_element::<IgnoredAny>()?.is_some() {
            len += 1;
        }
        if len > N {
            return Err(A::Error::invalid_length(len, &self));
        }
        let array = items
            .try_into()
            .map_err(|_| A::Error::custom("array length"))?;
        Ok(Exact(array))
    }
}

impl<T: Serialize, const N: usize> Serialize for Exact<T, N> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut tuple = serializer.serialize_tuple(N)?;
        for item in &self.0 {
            tuple.serialize_element(item)?;
        }
        tuple.end()
    }
}
