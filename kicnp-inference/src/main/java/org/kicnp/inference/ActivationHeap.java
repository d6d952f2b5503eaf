package org.kicnp.inference;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The agenda's queue: a binary heap in {@link Agenda#ORDER}, each activation knowing its place in it, so that taking
 * the first, adding one and withdrawing any one cost O(log n) with no allocation per entry (a tree set allocates a
 * node per activation and rebalances). The order is total (activations made at once are told apart by their sequence
 * number), so the heap fires in exactly the order a sorted set would. Owned by the engine thread.
 */
final class ActivationHeap {
    private Activation[] heap = new Activation[64];
    private int size;

    int size() {
        return size;
    }

    void add(Activation a) {
        if (size == heap.length) {
            heap = Arrays.copyOf(heap, size * 2);
        }
        heap[size] = a;
        a.heapIndex = size;
        size++;
        up(a.heapIndex);
    }

    /** The first activation in agenda order, left queued; null when there is none. */
    Activation peek() {
        return size == 0 ? null : heap[0];
    }

    /** Takes the first activation in agenda order; null when there is none. */
    Activation poll() {
        if (size == 0) {
            return null;
        }
        Activation first = heap[0];
        removeAt(0);
        return first;
    }

    /** Withdraws an activation; false when it is not queued. */
    boolean remove(Activation a) {
        int i = a.heapIndex;
        if (i < 0 || i >= size || heap[i] != a) {
            return false;
        }
        removeAt(i);
        return true;
    }

    void clear() {
        for (int i = 0; i < size; i++) {
            heap[i].heapIndex = -1;
        }
        Arrays.fill(heap, 0, size, null);
        size = 0;
    }

    /** The queued activations in no particular order (a copy). */
    List<Activation> snapshot() {
        return new ArrayList<>(Arrays.asList(heap).subList(0, size));
    }

    /** The queued activations in agenda order (a sorted copy). */
    List<Activation> inOrder() {
        List<Activation> out = snapshot();
        out.sort(Agenda.ORDER);
        return out;
    }

    private void removeAt(int i) {
        Activation gone = heap[i];
        gone.heapIndex = -1;
        size--;
        if (i == size) {
            heap[size] = null;
            return;
        }
        Activation last = heap[size];
        heap[size] = null;
        heap[i] = last;
        last.heapIndex = i;
        if (!up(i)) {
            down(i);
        }
    }

    /** Moves the entry at {@code i} up while it comes before its parent; answers whether it moved. */
    private boolean up(int i) {
        Activation a = heap[i];
        int start = i;
        while (i > 0) {
            int parent = (i - 1) >>> 1;
            Activation p = heap[parent];
            if (Agenda.ORDER.compare(a, p) >= 0) {
                break;
            }
            heap[i] = p;
            p.heapIndex = i;
            i = parent;
        }
        heap[i] = a;
        a.heapIndex = i;
        return i != start;
    }

    private void down(int i) {
        Activation a = heap[i];
        int half = size >>> 1;
        while (i < half) {
            int child = 2 * i + 1;
            int right = child + 1;
            if (right < size && Agenda.ORDER.compare(heap[right], heap[child]) < 0) {
                child = right;
            }
            if (Agenda.ORDER.compare(a, heap[child]) <= 0) {
                break;
            }
            heap[i] = heap[child];
            heap[i].heapIndex = i;
            i = child;
        }
        heap[i] = a;
        a.heapIndex = i;
    }
}
