package org.kicnp.inference;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The agenda's queue, in exactly {@link Agenda#ORDER}, shaped for the way activations arrive: one lane per rule rank
 * (priority, depth, conditions: a constant of the rule), and in a lane the activations of each recency kept in the
 * order they were made. A new fact's bindings carry the newest stamp there is, so they nearly always arrive in order:
 * they start a new recency group on top of their lane, or join the end of the top one. That costs O(1) to add and to
 * take, against the O(log n) sift of a heap through tens of thousands of waiting activations (a batch of stimuli
 * matched before the first firing). An activation that arrives out of order (an older binding matched again, after a
 * claim on it was freed) goes to the lane's {@link ActivationHeap}; taking compares the heads of the two.
 *
 * <p>A withdrawn activation left in a group is only marked ({@link Activation#stacked} cleared) and skipped when its
 * turn comes, so withdrawal costs O(1) too; an activation once taken or withdrawn is never added again (the engine
 * makes a new one for a binding matched again). Owned by the engine thread.
 */
final class ActivationQueue {
    /** Lanes by rank, highest first. */
    private Lane[] lanes = new Lane[0];
    private long[] ranks = new long[0];
    /** Index of the first lane that may hold an activation; every lane before it is empty. */
    private int first;
    private int size;

    int size() {
        return size;
    }

    void add(Activation a) {
        lane(a.rank()).add(a);
        size++;
    }

    /** Takes the first activation in agenda order; null when there is none. */
    Activation poll() {
        while (first < lanes.length) {
            Activation a = lanes[first].poll();
            if (a != null) {
                size--;
                return a;
            }
            first++;
        }
        return null;
    }

    /** Withdraws an activation; false when it is not queued. */
    boolean remove(Activation a) {
        boolean removed;
        if (a.stacked) {
            a.stacked = false;
            lanes[indexOf(a.rank())].live--;
            removed = true;
        } else {
            int i = indexOf(a.rank());
            removed = i >= 0 && lanes[i].heap.remove(a);
        }
        if (removed) {
            size--;
        }
        return removed;
    }

    void clear() {
        for (Lane l : lanes) {
            l.clear();
        }
        size = 0;
        first = lanes.length;
    }

    /** The queued activations in no particular order (a copy). */
    List<Activation> snapshot() {
        List<Activation> out = new ArrayList<>(size);
        for (Lane l : lanes) {
            l.collect(out);
        }
        return out;
    }

    /** The queued activations in agenda order (a sorted copy). */
    List<Activation> inOrder() {
        List<Activation> out = snapshot();
        out.sort(Agenda.ORDER);
        return out;
    }

    private int indexOf(long rank) {
        // Ranks are kept highest first: search the negated, ascending.
        int lo = 0;
        int hi = ranks.length - 1;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            long r = ranks[mid];
            if (r == rank) {
                return mid;
            }
            if (r > rank) {
                lo = mid + 1;
            } else {
                hi = mid - 1;
            }
        }
        return -(lo + 1);
    }

    private Lane lane(long rank) {
        int i = indexOf(rank);
        if (i < 0) {
            i = -(i + 1);
            Lane l = new Lane();
            lanes = insert(lanes, i, l);
            long[] r = new long[ranks.length + 1];
            System.arraycopy(ranks, 0, r, 0, i);
            r[i] = rank;
            System.arraycopy(ranks, i, r, i + 1, ranks.length - i);
            ranks = r;
        }
        if (i < first) {
            first = i;
        }
        return lanes[i];
    }

    private static Lane[] insert(Lane[] a, int i, Lane l) {
        Lane[] out = new Lane[a.length + 1];
        System.arraycopy(a, 0, out, 0, i);
        out[i] = l;
        System.arraycopy(a, i, out, i + 1, a.length - i);
        return out;
    }

    /**
     * The activations of one rank. {@code stack} holds recency groups, oldest recency at the bottom; each group is
     * contiguous, in the order its activations were made, from {@code groupStart[g]}; {@code groupHead[g]} is its
     * next one to take. So the head of the top group is the lane's first activation in agenda order, unless the
     * heap's first comes before it.
     */
    private static final class Lane {
        private Activation[] stack = new Activation[16];
        private int height;
        private int[] groupStart = new int[8];
        private int[] groupHead = new int[8];
        private long[] groupRecency = new long[8];
        private int groups;
        /** Activations in the stack not yet taken or withdrawn. */
        int live;
        final ActivationHeap heap = new ActivationHeap();

        void add(Activation a) {
            long recency = a.recency();
            if (groups > 0 && (recency < groupRecency[groups - 1]
                    || recency == groupRecency[groups - 1] && a.seq() < stack[height - 1].seq())) {
                heap.add(a); // out of order: an older binding matched again
                return;
            }
            if (groups == 0 || recency > groupRecency[groups - 1]) {
                if (groups == groupStart.length) {
                    groupStart = Arrays.copyOf(groupStart, groups * 2);
                    groupHead = Arrays.copyOf(groupHead, groups * 2);
                    groupRecency = Arrays.copyOf(groupRecency, groups * 2);
                }
                groupStart[groups] = height;
                groupHead[groups] = height;
                groupRecency[groups] = recency;
                groups++;
            }
            if (height == stack.length) {
                stack = Arrays.copyOf(stack, height * 2);
            }
            stack[height++] = a;
            a.stacked = true;
            live++;
        }

        Activation poll() {
            Activation top = stackHead();
            Activation h = heap.size() == 0 ? null : heap.peek();
            if (top == null && h == null) {
                return null;
            }
            if (top == null || h != null && Agenda.ORDER.compare(h, top) < 0) {
                return heap.poll();
            }
            int g = groups - 1;
            stack[groupHead[g]++] = null;
            top.stacked = false;
            live--;
            dropSpentGroups();
            return top;
        }

        /** The first activation of the stack in agenda order, after dropping withdrawn ones; null when none. */
        private Activation stackHead() {
            while (groups > 0) {
                int g = groups - 1;
                while (groupHead[g] < height) {
                    Activation a = stack[groupHead[g]];
                    if (a.stacked) {
                        return a;
                    }
                    stack[groupHead[g]++] = null; // withdrawn
                }
                dropSpentGroups();
            }
            return null;
        }

        private void dropSpentGroups() {
            while (groups > 0 && groupHead[groups - 1] == height) {
                groups--;
                height = groupStart[groups];
            }
            if (live == 0 && height > 0) {
                // Only withdrawn activations are left in the groups below: forget them.
                Arrays.fill(stack, 0, height, null);
                height = 0;
                groups = 0;
            }
        }

        void clear() {
            for (int i = 0; i < height; i++) {
                if (stack[i] != null) {
                    stack[i].stacked = false;
                    stack[i] = null;
                }
            }
            height = 0;
            groups = 0;
            live = 0;
            heap.clear();
        }

        void collect(List<Activation> out) {
            for (int g = 0; g < groups; g++) {
                int end = g + 1 < groups ? groupStart[g + 1] : height;
                for (int i = groupHead[g]; i < end; i++) {
                    Activation a = stack[i];
                    if (a != null && a.stacked) {
                        out.add(a);
                    }
                }
            }
            out.addAll(heap.snapshot());
        }
    }
}
