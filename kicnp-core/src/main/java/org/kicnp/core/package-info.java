/**
 * The frame model of K-ICNP and the knowledge base that holds it: frames with an IS-A hierarchy, has-part,
 * semantic links and slots carrying every facet of the paper's Table 2, plus the thread-safe
 * {@link org.kicnp.core.KnowledgeBase} aggregate that validates, indexes and publishes changes.
 */
package org.kicnp.core;
