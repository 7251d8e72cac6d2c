//! The operands of a CSG value, a list that `a | b | c | ...` extends in amortised constant
//! time.
//!
//! Why: values are immutable, so `acc | x` used to copy all of `acc`'s operands into a new
//! list to add one: a union grown by `reduce` over 20,000 objects made 200 million copies
//! (34 s, issue 35). Here views share one growing list: a view is the list's first `len`
//! items, and extending a view that ends where the list ends pushes in place (every older view
//! keeps its own length, so it still sees exactly its operands). Extending a view the list has
//! already grown past copies its items into a new list, as before: that only happens when one
//! value is extended twice, e.g. `let u = a | b; let v = u | c; let w = u | d`.

use std::cell::{Ref, RefCell};
use std::fmt;
use std::rc::Rc;

/// A view of the first `len` operands of a shared list (of objects, `value::Obj`; generic so
/// that this file stands below the values).
pub(crate) struct Operands<T> {
    shared: Rc<RefCell<Vec<T>>>,
    len: usize,
}

impl<T> Clone for Operands<T> {
    fn clone(&self) -> Operands<T> {
        Operands {
            shared: Rc::clone(&self.shared),
            len: self.len,
        }
    }
}

impl<T: Clone> Operands<T> {
    /// A view of all of `items`.
    pub(crate) fn new(items: Vec<T>) -> Operands<T> {
        let len = items.len();
        Operands {
            shared: Rc::new(RefCell::new(items)),
            len,
        }
    }

    /// How many operands.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// The operands, in order.
    pub(crate) fn items(&self) -> Ref<'_, [T]> {
        Ref::map(self.shared.borrow(), |v| &v[..self.len])
    }

    /// These operands followed by `more`, sharing this view's list when nothing was added
    /// after it yet.
    pub(crate) fn extended(&self, more: Vec<T>) -> Operands<T> {
        if let Ok(mut list) = self.shared.try_borrow_mut()
            && list.len() == self.len
        {
            list.extend(more);
            return Operands {
                shared: Rc::clone(&self.shared),
                len: list.len(),
            };
        }
        let mut fresh = self.items().to_vec();
        fresh.extend(more);
        Operands::new(fresh)
    }
}

impl<T: Clone + fmt::Debug> fmt::Debug for Operands<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.items().iter()).finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(o: &Operands<u32>) -> Vec<u32> {
        o.items().to_vec()
    }

    /// Every view keeps exactly its operands however the shared list grows, and extending an
    /// older view a second time copies instead of disturbing the newer one.
    #[test]
    fn views_keep_their_operands() {
        let a = Operands::new(vec![1]);
        let b = a.extended(vec![2]);
        let c = b.extended(vec![3, 4]);
        assert!(Rc::ptr_eq(&a.shared, &c.shared), "a chain shares one list");
        let d = b.extended(vec![5]);
        assert!(
            !Rc::ptr_eq(&b.shared, &d.shared),
            "a second extension copies"
        );
        assert_eq!(all(&a), [1]);
        assert_eq!(all(&b), [1, 2]);
        assert_eq!(all(&c), [1, 2, 3, 4]);
        assert_eq!(all(&d), [1, 2, 5]);
        assert_eq!((c.len(), d.len()), (4, 3));
    }

    /// Extending a view while its list is borrowed (the operand on the right shares it, as in
    /// `u | u`) copies rather than panicking.
    #[test]
    fn extending_while_borrowed_copies() {
        let a = Operands::new(vec![1, 2]);
        let held = a.items();
        let b = a.extended(vec![3]);
        drop(held);
        assert_eq!(all(&b), [1, 2, 3]);
        assert_eq!(all(&a), [1, 2]);
    }
}
