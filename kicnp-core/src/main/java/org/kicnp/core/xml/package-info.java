/**
 * The paper's XML format for frames (Table 4): {@link org.kicnp.core.xml.KnowledgeLoader} reads files into a
 * {@link org.kicnp.core.KnowledgeBase} in one all-or-nothing batch, reporting every error with its file, line and
 * column; {@link org.kicnp.core.xml.KnowledgeXmlWriter} writes frames back deterministically. Reading is hand-written
 * StAX over small located DTOs mapped explicitly to the domain types, with DTDs and external entities refused.
 * The format is described in {@code docs/xml-format.md} and {@code docs/kicnp-kb.xsd}.
 */
package org.kicnp.core.xml;
