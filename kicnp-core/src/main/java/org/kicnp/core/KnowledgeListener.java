package org.kicnp.core;

/**
 * Hears every committed batch, in commit order, after the knowledge base has changed and its lock is released.
 * A listener may change the knowledge base; the events of that change are delivered after the current ones.
 */
@FunctionalInterface
public interface KnowledgeListener {
    void changed(ChangeSet changes);
}
