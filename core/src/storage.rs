//! The ways the tracer reads storage it does not own (smoltcp's way: the caller owns it, the
//! core never allocates): a [`Table`] of a length fixed when it is made, a [`List`] that grows
//! up to a capacity, and the [`Index`] an object's number is kept in. Arrays and
//! `heapless::Vec` implement them here; a host implements them over its heap.
//!
//! A table baked into flash is a kind of storage, not a mode: [`InFlash`] is a table that
//! borrows a `'static` slice (heapless's `VecView` and smoltcp's `ManagedSlice` are the models),
//! so a prepared scene reads every table through one view (`slots`), whether it was prepared
//! into RAM or baked (`crate::bake`). [`Unset`] gives each storage its every-byte-zero value, so
//! that a scene to be prepared in place is a `static` in zero-initialised RAM.

use core::fmt::Debug;
use core::ops::{Deref, DerefMut};

/// The value of a storage before anything is kept in it: every byte zero where the type allows
/// (a `static` of it is zero-initialised RAM and takes no flash).
pub trait Unset: Sized {
    /// Nothing kept.
    const UNSET: Self;
}

/// A table of `T`s: one per object (or a fixed number per object), its length fixed when it
/// is made.
pub trait Table<T>: Clone + Sized {
    /// Whether the table is a view of one baked into flash ([`InFlash`]): it is read, never
    /// built, so a build whose table is one links none of the code that builds it.
    const BAKED: bool = false;
    /// Every slot.
    fn slots(&self) -> &[T];
    /// Every slot, to write (none for a table baked into flash).
    fn slots_mut(&mut self) -> &mut [T];
    /// A table of `count` slots, each `value`, or of as many as the storage holds (an array
    /// has its length whatever `count`; a table in flash holds nothing until it is given one).
    fn filled(count: usize, value: T) -> Self;
    /// Holds the table `baked` (made at build time, in flash) from now on, and how many of its
    /// slots it holds: a view keeps the slice itself, storage of its own copies what fits.
    fn hold(&mut self, baked: &'static [T]) -> usize
    where
        T: Copy,
    {
        let slots = self.slots_mut();
        let held = slots.len().min(baked.len());
        if let (Some(to), Some(from)) = (slots.get_mut(..held), baked.get(..held)) {
            to.copy_from_slice(from);
        }
        held
    }
}

/// A table baked into flash, borrowed: nothing until [`Table::hold`] gives it its `'static`
/// slice (`None`, so that an unprepared scene is all zeros), then exactly that slice.
#[derive(Debug)]
pub struct InFlash<T: 'static>(Option<&'static [T]>);

impl<T: 'static> Clone for InFlash<T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T: 'static> Copy for InFlash<T> {}

impl<T: 'static> InFlash<T> {
    /// The table `baked`.
    pub const fn new(baked: &'static [T]) -> Self {
        Self(Some(baked))
    }
}

impl<T: 'static> Unset for InFlash<T> {
    const UNSET: Self = Self(None);
}

impl<T: 'static> Table<T> for InFlash<T> {
    const BAKED: bool = true;

    #[inline(always)]
    fn slots(&self) -> &[T] {
        self.0.unwrap_or(&[])
    }

    #[inline(always)]
    fn slots_mut(&mut self) -> &mut [T] {
        &mut []
    }

    fn filled(_count: usize, _value: T) -> Self {
        Self(None)
    }

    fn hold(&mut self, baked: &'static [T]) -> usize
    where
        T: Copy,
    {
        self.0 = Some(baked);
        baked.len()
    }
}

impl<T: 'static> Deref for InFlash<T> {
    type Target = [T];

    #[inline(always)]
    fn deref(&self) -> &[T] {
        self.slots()
    }
}

impl<T: Unset, const K: usize> Unset for [T; K] {
    const UNSET: Self = [T::UNSET; K];
}

impl<T, const K: usize> Unset for heapless::Vec<T, K> {
    const UNSET: Self = heapless::Vec::new();
}

impl<T> Unset for Option<T> {
    const UNSET: Self = None;
}

impl<A: Unset, B: Unset> Unset for (A, B) {
    const UNSET: Self = (A::UNSET, B::UNSET);
}

impl Unset for u8 {
    const UNSET: Self = 0;
}

impl Unset for u16 {
    const UNSET: Self = 0;
}

impl Unset for u32 {
    const UNSET: Self = 0;
}

impl Unset for usize {
    const UNSET: Self = 0;
}

impl Unset for bool {
    const UNSET: Self = false;
}

impl<T: Copy, const K: usize> Table<T> for [T; K] {
    #[inline(always)]
    fn slots(&self) -> &[T] {
        self
    }

    #[inline(always)]
    fn slots_mut(&mut self) -> &mut [T] {
        self
    }

    #[inline(always)]
    fn filled(_count: usize, value: T) -> Self {
        [value; K]
    }
}

/// `A` slots for each of `B` objects, read as one slice of `A·B` (the grid's pool).
impl<T: Copy, const A: usize, const B: usize> Table<T> for [[T; A]; B] {
    #[inline(always)]
    fn slots(&self) -> &[T] {
        self.as_flattened()
    }

    #[inline(always)]
    fn slots_mut(&mut self) -> &mut [T] {
        self.as_flattened_mut()
    }

    #[inline(always)]
    fn filled(_count: usize, value: T) -> Self {
        [[value; A]; B]
    }
}

/// A list of at most `K` `T`s, in the type (what a baked scene's `Config` names).
pub type Capped<T, const K: usize> = heapless::Vec<T, K>;

/// A list of at most a capacity of `T`s (`heapless::Vec` in [`Arrays`](crate::config::Arrays)).
pub trait List<T>: Deref<Target = [T]> + DerefMut + Default + Clone {
    /// The most items it holds (`usize::MAX`: as many as memory does).
    const CAPACITY: usize;
    /// Appends `item`, or gives it back when the list is full.
    fn push(&mut self, item: T) -> Result<(), T>;
    /// Removes and returns the last item.
    fn pop(&mut self) -> Option<T>;
    /// Empties the list.
    fn clear(&mut self);
    /// Keeps the first `len` items (all, when there are fewer).
    fn truncate(&mut self, len: usize) {
        while self.len() > len {
            self.pop();
        }
    }
}

/// A host's list as long as memory allows (the `alloc` feature: build scripts and host tools).
#[cfg(feature = "alloc")]
impl<T> Unset for alloc::vec::Vec<T> {
    const UNSET: Self = alloc::vec::Vec::new();
}

#[cfg(feature = "alloc")]
impl<T: Clone> List<T> for alloc::vec::Vec<T> {
    const CAPACITY: usize = usize::MAX;

    fn push(&mut self, item: T) -> Result<(), T> {
        alloc::vec::Vec::push(self, item);
        Ok(())
    }

    fn pop(&mut self) -> Option<T> {
        alloc::vec::Vec::pop(self)
    }

    fn clear(&mut self) {
        alloc::vec::Vec::clear(self);
    }
}

impl<T: Clone, const K: usize> List<T> for heapless::Vec<T, K> {
    const CAPACITY: usize = K;

    #[inline(always)]
    fn push(&mut self, item: T) -> Result<(), T> {
        heapless::Vec::push(self, item)
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<T> {
        heapless::Vec::pop(self)
    }

    #[inline(always)]
    fn clear(&mut self) {
        heapless::Vec::clear(self)
    }

    #[inline(always)]
    fn truncate(&mut self, len: usize) {
        heapless::Vec::truncate(self, len)
    }
}

/// An object's number as the tables keep it, and a place in the grid's pool: `u16` on a
/// microcontroller (65,535 objects and pool entries at most, two bytes each), `u32` where a
/// scene may be larger.
pub trait Index: Copy + Default + Ord + Debug + Unset + 'static {
    /// The largest value it holds: the tables hold at most this many objects and entries.
    const MAX: usize;
    /// `value`, at most [`Index::MAX`] (callers cap it; a larger one would wrap).
    fn new(value: usize) -> Self;
    /// The value.
    fn get(self) -> usize;
}

impl Index for u16 {
    const MAX: usize = u16::MAX as usize;

    #[inline(always)]
    fn new(value: usize) -> Self {
        value as u16
    }

    #[inline(always)]
    fn get(self) -> usize {
        usize::from(self)
    }
}

impl Index for u32 {
    const MAX: usize = if usize::BITS < 32 { usize::MAX } else { u32::MAX as usize };

    #[inline(always)]
    fn new(value: usize) -> Self {
        value as u32
    }

    #[inline(always)]
    fn get(self) -> usize {
        self as usize
    }
}
