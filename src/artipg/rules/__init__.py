"""Category-rule framework: the parameter recorder and the slot DAG."""

from artipg.rules.category import Category, Slot, SlotContext
from artipg.rules.params import Param, ParamRecorder

__all__ = ["Category", "Slot", "SlotContext", "Param", "ParamRecorder"]
