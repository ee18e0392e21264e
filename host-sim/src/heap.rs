//! The host's storage: every table of the tracer sized at run time by the scene, on the heap
//! (the core never allocates: it reads these through `microtrace::storage`'s traits). A host
//! scene holds as many objects as memory does; the firmware keeps its arrays sized at build
//! time (`config::Arrays`).

use std::marker::PhantomData;
use std::ops::{Deref, DerefMut};

use microtrace::config::{Config, SolidStorage, DEFAULT_GRID_ENTRIES_PER_OBJECT, DEFAULT_TREE_DEPTH};
use microtrace::model::{Object, PreparedSolidNode, MAX_HELD_SPANS, MAX_SOLID_STACK, MAX_SPANS};
use microtrace::number::Number;
use microtrace::scene::Prepared;
use microtrace::storage::{List, Table, Unset};

/// A table of a length fixed when it is made, on the heap.
#[derive(Clone, Debug)]
pub struct Boxed<T>(Vec<T>);

impl<T> Unset for Boxed<T> {
    const UNSET: Self = Self(Vec::new());
}

impl<T: Copy> Table<T> for Boxed<T> {
    fn slots(&self) -> &[T] {
        &self.0
    }

    fn slots_mut(&mut self) -> &mut [T] {
        &mut self.0
    }

    fn filled(count: usize, value: T) -> Self {
        Self(vec![value; count])
    }

    fn hold(&mut self, baked: &'static [T]) -> usize {
        self.0 = baked.to_vec();
        baked.len()
    }
}

/// A list that grows as long as memory lasts.
#[derive(Clone, Debug, PartialEq)]
pub struct Growing<T>(Vec<T>);

impl<T> Unset for Growing<T> {
    const UNSET: Self = Self(Vec::new());
}

impl<T> Default for Growing<T> {
    fn default() -> Self {
        Self(Vec::new())
    }
}

impl<T> Deref for Growing<T> {
    type Target = [T];

    fn deref(&self) -> &[T] {
        &self.0
    }
}

impl<T> DerefMut for Growing<T> {
    fn deref_mut(&mut self) -> &mut [T] {
        &mut self.0
    }
}

impl<'a, T> IntoIterator for &'a Growing<T> {
    type Item = &'a T;
    type IntoIter = std::slice::Iter<'a, T>;

    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}

impl<T: Clone> List<T> for Growing<T> {
    const CAPACITY: usize = usize::MAX;

    fn push(&mut self, item: T) -> Result<(), T> {
        self.0.push(item);
        Ok(())
    }

    fn pop(&mut self) -> Option<T> {
        self.0.pop()
    }

    fn clear(&mut self) {
        self.0.clear();
    }
}

/// The host's [`Config`]: the number type `N`, every table on the heap and sized by the scene,
/// objects numbered in `u32`.
#[derive(Debug)]
pub struct Heap<N>(PhantomData<N>);

/// The grid's pool holds at least this many objects' entries: what the host's fixed tables
/// held before they were sized by the scene (512 objects), so that a small scene keeps the
/// grid it had (a pool of 24 entries an object overflows on a scene whose objects cover many
/// cells, and the grid then switches off).
const GRID_POOL_OBJECTS_AT_LEAST: usize = 512;

impl<N: Number> Config for Heap<N> {
    type Number = N;
    type Index = u32;
    type Objects = Growing<Object<N>>;
    type Solids = Growing<PreparedSolidNode<N>>;
    type Palette = microtrace::config::OwnedPalette;
    type PerObject<T: Copy> = Boxed<T>;
    type ViewTable<T: Copy + Unset + 'static> = Boxed<T>;
    type PerObjectPerOtherLight<T: Copy> = Boxed<T>;
    type OtherLights<T: Clone> = heapless::Vec<T, { microtrace::model::MAX_LIGHTS - 1 }>;
    type PerObjectList<T: Clone> = Growing<T>;
    type GridPool<T: Copy + Unset + 'static> = Boxed<T>;
    type SpaceEntries = Boxed<u32>;
    type BlockerLists = Boxed<u32>;
    type Hierarchy<T: Copy + Unset + 'static> = Boxed<T>;
    type ScreenCells<T: Copy + Unset + 'static> = Boxed<T>;
    type LightTables<T: Copy + Unset + 'static> = [T; 0];
    type TreeStack<T: Clone> = heapless::Vec<T, DEFAULT_TREE_DEPTH>;
    type CornerRow = Boxed<[u8; 3]>;
    const MAX_OBJECTS: usize = usize::MAX;
    const GRID_ENTRIES_PER_OBJECT: usize = DEFAULT_GRID_ENTRIES_PER_OBJECT;
    const TREE_DEPTH: usize = DEFAULT_TREE_DEPTH;
    const BLOCKER_LISTS: bool = true;
    const HIERARCHY: bool = true;

    fn grid_entries(objects: usize) -> usize {
        objects.max(GRID_POOL_OBJECTS_AT_LEAST).saturating_mul(Self::GRID_ENTRIES_PER_OBJECT)
    }
}

/// The solids' nodes on the heap; a ray's walk keeps its lists on the stack (an allocation per
/// ray would cost more than the walk), within the format's limits.
impl<N> SolidStorage<N> for Growing<PreparedSolidNode<N>> {
    type HeldSpans<T: Clone> = heapless::Vec<T, MAX_HELD_SPANS>;
    type Spans<T: Clone> = heapless::Vec<T, MAX_SPANS>;
    type Lists<T: Clone> = heapless::Vec<T, MAX_SOLID_STACK>;
}

/// A scene prepared in the number type `N`, its tables on the heap.
pub type HostPrepared<N> = Prepared<Heap<N>>;
