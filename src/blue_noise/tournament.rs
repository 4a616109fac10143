//! A tournament tree over pixel keys: the index of the best key (largest for [`Best::Max`],
//! smallest for [`Best::Min`], the lower index on ties) in `O(1)`, a change of a run of `m`
//! consecutive keys in `O(m + log n)`.

/// Which key wins.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Best {
    Max,
    Min,
}

/// The tree: `vals` padded to a power of two `p` with a losing sentinel, `win[i]` the
/// winning leaf below internal node `i` (`1 <= i < p`).
#[derive(Clone, Debug)]
pub(crate) struct Tournament {
    best: Best,
    p: usize,
    vals: Vec<i64>,
    win: Vec<u32>,
}

impl Tournament {
    /// The key that never wins.
    pub(crate) fn sentinel(best: Best) -> i64 {
        match best {
            Best::Max => i64::MIN,
            Best::Min => i64::MAX,
        }
    }

    /// A tree over `vals` (at most 2^31 of them), its `12 p` bytes (`p` the next power of
    /// two) checked by [`crate::size`].
    ///
    /// # Errors
    /// [`crate::Error::TooLarge`] past the allocation limit.
    pub(crate) fn new(best: Best, vals: &[i64]) -> crate::Result<Self> {
        let p = vals.len().next_power_of_two().max(2);
        let mut v = crate::size::vec_zeroed::<i64>(p)?;
        v.fill(Self::sentinel(best));
        if let Some(head) = v.get_mut(..vals.len()) {
            head.copy_from_slice(vals);
        }
        let mut t = Tournament {
            best,
            p,
            vals: v,
            win: crate::size::vec_zeroed::<u32>(p)?,
        };
        for i in (1..p).rev() {
            t.recompute(i);
        }
        Ok(t)
    }

    #[inline]
    fn better(&self, a: u32, b: u32) -> u32 {
        let (va, vb) = (self.val(a as usize), self.val(b as usize));
        let a_wins = match self.best {
            Best::Max => va > vb || (va == vb && a < b),
            Best::Min => va < vb || (va == vb && a < b),
        };
        if a_wins { a } else { b }
    }

    #[inline]
    fn val(&self, i: usize) -> i64 {
        self.vals
            .get(i)
            .copied()
            .unwrap_or(Self::sentinel(self.best))
    }

    /// The winner below node `i` (a leaf when `i >= p`).
    #[inline]
    fn winner(&self, i: usize) -> u32 {
        if i >= self.p {
            (i - self.p) as u32
        } else {
            self.win.get(i).copied().unwrap_or(0)
        }
    }

    #[inline]
    fn recompute(&mut self, i: usize) {
        let w = self.better(self.winner(2 * i), self.winner(2 * i + 1));
        if let Some(slot) = self.win.get_mut(i) {
            *slot = w;
        }
    }

    /// The winning index, `None` when every key is the sentinel.
    pub(crate) fn top(&self) -> Option<usize> {
        let w = self.winner(1) as usize;
        (self.val(w) != Self::sentinel(self.best)).then_some(w)
    }

    /// Sets key `i` without updating the tree (call [`refresh`](Self::refresh) after).
    #[inline]
    pub(crate) fn set(&mut self, i: usize, v: i64) {
        if let Some(slot) = self.vals.get_mut(i) {
            *slot = v;
        }
    }

    /// Adds `dv` to key `i` unless it is the sentinel (no tree update).
    #[inline]
    pub(crate) fn add(&mut self, i: usize, dv: i64) {
        let s = Self::sentinel(self.best);
        if let Some(slot) = self.vals.get_mut(i)
            && *slot != s
        {
            *slot += dv;
        }
    }

    /// Updates the tree above the leaves `lo..=hi`.
    pub(crate) fn refresh(&mut self, lo: usize, hi: usize) {
        let (mut a, mut b) = ((self.p + lo) / 2, (self.p + hi) / 2);
        while a >= 1 {
            for i in a..=b {
                self.recompute(i);
            }
            a /= 2;
            b /= 2;
        }
    }
}
