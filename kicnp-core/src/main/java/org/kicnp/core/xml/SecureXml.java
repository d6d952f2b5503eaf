package org.kicnp.core.xml;

import com.ctc.wstx.api.WstxInputProperties;
import com.fasterxml.jackson.dataformat.xml.XmlFactory;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLResolver;
import javax.xml.stream.XMLStreamException;

/**
 * The StAX factory every knowledge file is read with: Jackson's Woodstox, with DTDs and external entities off, any
 * resolver refusing, and limits on depth, text and attribute size, so a hostile file fails fast instead of expanding
 * entities or reading local files.
 */
final class SecureXml {
    /** Default cap on one file's size in bytes; override with the system property {@value #MAX_BYTES_PROPERTY}. */
    static final long DEFAULT_MAX_FILE_BYTES = 512L * 1024 * 1024;
    static final String MAX_BYTES_PROPERTY = "kicnp.xml.maxFileBytes";
    static final int MAX_DEPTH = 64;
    static final int MAX_TEXT = 4 * 1024 * 1024;

    private SecureXml() {
    }

    static XMLInputFactory inputFactory() {
        XMLInputFactory f = new XmlFactory().getXMLInputFactory();
        XMLResolver refuse = (publicId, systemId, baseUri, namespace) -> {
            throw new XMLStreamException("External entities and DTDs are not allowed ('" + systemId + "').");
        };
        f.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        f.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        f.setProperty(XMLInputFactory.IS_REPLACING_ENTITY_REFERENCES, true);
        // Not coalescing, so that the reader sees CDATA sections: text in CDATA is taken as written, never as absent.
        f.setProperty(XMLInputFactory.IS_COALESCING, false);
        // Knowledge files use no namespaces; without namespace processing Woodstox does less work per element.
        f.setProperty(XMLInputFactory.IS_NAMESPACE_AWARE, false);
        f.setProperty(XMLInputFactory.RESOLVER, refuse);
        f.setProperty(WstxInputProperties.P_DTD_RESOLVER, refuse);
        f.setProperty(WstxInputProperties.P_ENTITY_RESOLVER, refuse);
        f.setProperty(WstxInputProperties.P_MAX_ELEMENT_DEPTH, MAX_DEPTH);
        f.setProperty(WstxInputProperties.P_MAX_TEXT_LENGTH, MAX_TEXT);
        f.setProperty(WstxInputProperties.P_MAX_ATTRIBUTE_SIZE, 64 * 1024);
        f.setProperty(WstxInputProperties.P_MAX_ATTRIBUTES_PER_ELEMENT, 64);
        f.setProperty(WstxInputProperties.P_MAX_ENTITY_COUNT, 100);
        f.setProperty(WstxInputProperties.P_MAX_ENTITY_DEPTH, 2);
        return f;
    }

    static long maxFileBytes() {
        String v = System.getProperty(MAX_BYTES_PROPERTY);
        if (v == null || v.isBlank()) {
            return DEFAULT_MAX_FILE_BYTES;
        }
        try {
            return Long.parseLong(v.strip());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("System property " + MAX_BYTES_PROPERTY + " must be a number of bytes, "
                    + "not '" + v + "'.");
        }
    }
}
