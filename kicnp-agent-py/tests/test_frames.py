"""Frames as XML, without a gateway: what frame_xml writes and what Frame.parse reads back."""
import unittest

from kicnp_agent import Frame, ProtocolError, Ref, frame_xml


class FramesTest(unittest.TestCase):

    def test_frameXml_writesTypedSlots_andParseReadsThemBack(self):
        xml = frame_xml("cup9", "Cup", instance=True, slots={"ml": 250, "full": True, "temp": 61.5, "colour": "blue",
                                                              "owner": Ref("ken"), "sips": [3, 4]})
        self.assertIn("<SLOT><NAME>ml</NAME><TYPE>TYPE_INT</TYPE><VALUE>250</VALUE></SLOT>", xml)
        self.assertIn("<SLOT><NAME>sips</NAME><TYPE>TYPE_LIST</TYPE><ARGUMENT>TYPE_INT</ARGUMENT>"
                      "<VALUE><ITEM>3</ITEM><ITEM>4</ITEM></VALUE></SLOT>", xml)
        frame = Frame.parse(xml)
        self.assertEqual(("cup9", "Cup", True), (frame.name, frame.isa, frame.is_instance))
        self.assertEqual({"ml": 250, "full": True, "temp": 61.5, "colour": "blue", "owner": Ref("ken"), "sips": [3, 4]},
                         frame.slots)

    def test_frameXml_keepsTextTheReaderWouldTakeForAbsent_andEscapesMarkup(self):
        frame = Frame.parse(frame_xml("note", slots={"a": "", "b": " x ", "c": "NULL", "d": "<b> & ]]>"}))
        self.assertEqual({"a": "", "b": " x ", "c": "NULL", "d": "<b> & ]]>"}, frame.slots)
        self.assertEqual((None, False), (frame.isa, frame.is_instance))

    def test_frameXml_refusesWhatASlotCannotHold(self):
        with self.assertRaises(TypeError) as error:
            frame_xml("cup", slots={"mixed": [1, "two"]})
        self.assertEqual("Slot 'mixed' of frame 'cup' lists TYPE_INT, TYPE_STR; a list here holds items of one of "
                         "str, int, float, bool.", str(error.exception))
        with self.assertRaises(ValueError):
            frame_xml("cup", slots={"temp": float("nan")})
        with self.assertRaises(TypeError):
            frame_xml("cup", slots={"shape": {"round": True}})

    def test_parse_readsNestedListsAndTheEmptyList(self):
        frame = Frame.parse("<FRAME><NAME>signal_r_face</NAME><ISA>SensorSignal</ISA><ISINSTANCE>TRUE</ISINSTANCE>"
                            "<SLOTLIST><SLOT><NAME>values</NAME><TYPE>TYPE_LIST</TYPE><VALUE><ITEM>ken</ITEM><ITEM>"
                            "<ITEM>0.1</ITEM><ITEM>0.2</ITEM></ITEM></VALUE></SLOT><SLOT><NAME>none</NAME>"
                            "<TYPE>TYPE_LIST</TYPE><VALUE>[]</VALUE></SLOT></SLOTLIST></FRAME>")
        self.assertEqual({"values": ["ken", ["0.1", "0.2"]], "none": []}, frame.slots)

    def test_parse_refusesWhatIsNotAFrame(self):
        with self.assertRaises(ProtocolError) as error:
            Frame.parse("<FRAME><NAME>x</NAME>")
        self.assertTrue(str(error.exception).startswith("The server sent a frame that is not XML"))
        with self.assertRaises(ProtocolError):
            Frame.parse("<SLOT><NAME>x</NAME></SLOT>")


if __name__ == "__main__":
    unittest.main()
