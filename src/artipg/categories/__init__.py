"""The explicit category registry: name -> :class:`artipg.rules.Category`.

Adding a category: write ``categories/<name>.py`` defining ``RULE`` and add the module
to ``_MODULES`` below (a test checks every module here is registered).
"""

from __future__ import annotations

from artipg.categories import storage_furniture, eyeglasses, stapler, bottle, switch, bucket, microwave, faucet, kitchen_pot, kettle
from artipg.categories import safe, box, laptop, door, window, trash_can
from artipg.categories import table, chair, refrigerator, dishwasher, oven, washing_machine
from artipg.categories import display, globe, mug, pen, glue_stick, usb
from artipg.categories import scissors, pliers, knife
from artipg.categories import toaster, remote, keyboard, suitcase
from artipg.categories import dispenser, shampoo, shaver
from artipg.categories import clip, ruler, lighter
from artipg.categories import clock, fan, lamp
from artipg.categories import door_handle, folding_rack
from artipg.categories import toilet, coffee_machine, printer
from artipg.categories import camera, mouse, phone, cart

_MODULES = (storage_furniture, eyeglasses, stapler, bottle, switch, bucket, microwave, faucet, kitchen_pot, kettle,
            safe, box, laptop, door, window, trash_can,
            table, chair, refrigerator, dishwasher, oven, washing_machine,
            display, globe, mug, pen, glue_stick, usb,
            scissors, pliers, knife,
            toaster, remote, keyboard, suitcase,
            dispenser, shampoo, shaver,
            clip, ruler, lighter,
            clock, fan, lamp,
            door_handle, folding_rack,
            toilet, coffee_machine, printer,
            camera, mouse, phone, cart,
            )

REGISTRY = {m.RULE.name: m.RULE for m in _MODULES}
