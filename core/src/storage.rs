//! The three ways the tracer reads storage it does not own (smoltcp's way: the caller owns
//! it, the core never allocates): a [`Table`] of a length fixed when it is made, a [`List`] that
//! grows up to a capacity, and the [`Index`] an object's number is kept in. Arrays and
//! `heapless::Vec` implement them here; a host implements them over its heap.

use core::fmt::Debug;
use core::ops::{Deref, DerefMut};

/// A table of `T`s: one per object (or a fixed number per object), its length fixed when it
/// is made.
pub trait Table<T>: Clone + Sized {
    /// Every slot.
    fn slots(&self) -> &[T];
    /// Every slot, to write.
    fn slots_mut(&mut self) -> &mut [T];
    /// A table of `count` slots, each `value`, or of as many as the storage holds (an array
    /// has its length whatever `count`).
    fn filled(count: usize, value: T) -> Self;
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

/// A list of at most a capacity of `T`s (`heapless::Vec` in [`Arrays`]).
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
pub trait Index: Copy + Default + Ord + Debug + 'static {
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
