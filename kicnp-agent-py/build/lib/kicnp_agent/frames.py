"""Frames as they travel: the paper's XML (docs/xml-format.md), read into a small read-only :class:`Frame`, and
written from Python values by :func:`frame_xml` for capabilities and asserted instances.

This is not the knowledge model: the server checks every frame it receives against its own. The reader keeps what
an agent's program needs (name, parent, whether it is an instance, slot values typed by the slot's TYPE).
"""
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass
from typing import Dict, Optional
from xml.sax.saxutils import escape

from .errors import ProtocolError
from .messages import Ref

_SCALARS = {"TYPE_STR": str, "TYPE_INT": int, "TYPE_FLOAT": float}


@dataclass(frozen=True)
class Frame:
    """One frame as the server sent it: ``slots`` maps each slot that has a value to that value; ``xml`` is the text."""
    name: str
    isa: Optional[str]
    is_instance: bool
    slots: Dict[str, object]
    xml: str

    @staticmethod
    def parse(xml):
        """Reads one ``FRAME`` element; a :class:`ProtocolError` naming the problem when it is not one."""
        try:
            root = ElementTree.fromstring(xml)
        except ElementTree.ParseError as e:
            raise ProtocolError("The server sent a frame that is not XML (%s): %.80s" % (e, xml)) from None
        name = _text(root, "NAME")
        if root.tag != "FRAME" or not name:
            raise ProtocolError("The server sent a frame without FRAME and NAME: %.80s" % xml)
        slots = {}
        for slot in root.iterfind("SLOTLIST/SLOT"):
            value, data_type = slot.find("VALUE"), _text(slot, "TYPE").upper()
            # The server writes VALUE only for a slot that has one: empty text there is the empty string.
            if value is not None and (len(value) or (value.text or "") or data_type in ("TYPE_STR", "")):
                slots[_text(slot, "NAME")] = _value(value, data_type, _text(slot, "ARGUMENT"))
        return Frame(name, _text(root, "ISA") or None, _text(root, "ISINSTANCE").upper() == "TRUE", slots, xml)


def _text(element, tag):
    child = element.find(tag)
    return "" if child is None or child.text is None else child.text.strip()


def _value(element, data_type, argument):
    if data_type == "TYPE_LIST":
        item_type = argument.upper() if argument.upper() in _SCALARS or argument.upper() == "TYPE_BOOL" else (
            "TYPE_INSTANCE" if argument and not argument.upper().startswith("TYPE_") else "TYPE_STR")
        if not len(element) and (element.text or "").strip() == "[]":
            return []
        return [_item(item, item_type) for item in element.iterfind("ITEM")]
    return _scalar(element.text or "", data_type)


def _item(item, item_type):
    if len(item):  # a list inside a list of text
        return [_item(inner, "TYPE_STR") for inner in item.iterfind("ITEM")]
    return _scalar(item.text or "", item_type)


def _scalar(text, data_type):
    if data_type == "TYPE_BOOL":
        return text.strip().upper() in ("TRUE", "YES", "1")
    if data_type in ("TYPE_INSTANCE", "TYPE_FRAME"):
        return Ref(text.strip())
    if data_type in ("TYPE_INT", "TYPE_FLOAT"):
        return _SCALARS[data_type](text.strip())
    return text


_TYPES = ((bool, "TYPE_BOOL"), (int, "TYPE_INT"), (float, "TYPE_FLOAT"), (str, "TYPE_STR"), (Ref, "TYPE_INSTANCE"))


def frame_xml(name, isa=None, instance=False, slots=None):
    """The XML of one frame: a class (a capability) or, with ``instance=True``, an instance (to assert).

    ``slots`` maps slot names to values; each slot's TYPE follows its Python type (str, int, float, bool, a
    :class:`Ref` to an instance, or a list of one of the scalar types). Text is escaped, so any string is safe.
    """
    parts = ["<FRAME><NAME>%s</NAME>" % escape(name)]
    if isa is not None:
        parts.append("<ISA>%s</ISA>" % escape(isa))
    parts.append("<ISINSTANCE>%s</ISINSTANCE><SLOTLIST>" % ("TRUE" if instance else "FALSE"))
    for slot, value in (slots or {}).items():
        parts.append(_slot_xml(name, slot, value))
    parts.append("</SLOTLIST></FRAME>")
    return "".join(parts)


def _slot_xml(frame, slot, value):
    if isinstance(value, (list, tuple)):
        item_type = {_type_name(frame, slot, item) for item in value}
        if len(item_type) > 1 or "TYPE_INSTANCE" in item_type:
            raise TypeError("Slot '%s' of frame '%s' lists %s; a list here holds items of one of str, int, float, bool."
                            % (slot, frame, ", ".join(sorted(item_type))))
        items = "".join("<ITEM>%s</ITEM>" % _text_of(item) for item in value) if value else "[]"
        argument = item_type.pop() if item_type else "TYPE_STR"
        return ("<SLOT><NAME>%s</NAME><TYPE>TYPE_LIST</TYPE><ARGUMENT>%s</ARGUMENT><VALUE>%s</VALUE></SLOT>"
                % (escape(slot), argument, items))
    return ("<SLOT><NAME>%s</NAME><TYPE>%s</TYPE><VALUE>%s</VALUE></SLOT>"
            % (escape(slot), _type_name(frame, slot, value), _text_of(value)))


def _type_name(frame, slot, value):
    for python_type, name in _TYPES:
        if isinstance(value, python_type):
            if python_type is float and value != value:
                raise ValueError("Slot '%s' of frame '%s' is NaN, which a frame cannot hold." % (slot, frame))
            return name
    raise TypeError("Slot '%s' of frame '%s' is a %s; a slot value is a str, int, float, bool, Ref or a list."
                    % (slot, frame, type(value).__name__))


def _text_of(value):
    if isinstance(value, bool):
        return "TRUE" if value else "FALSE"
    if isinstance(value, Ref):
        return escape(value.name)
    if isinstance(value, float):
        return {float("inf"): "Infinity", float("-inf"): "-Infinity"}.get(value, repr(value))
    if isinstance(value, str) and (not value or value.strip() != value or value.upper() == "NULL"):
        # The reader takes empty text, NULL and outer white space as "absent"; CDATA keeps them as written.
        return "<![CDATA[%s]]>" % value.replace("]]>", "]]]]><![CDATA[>")
    return escape(value) if isinstance(value, str) else str(value)
