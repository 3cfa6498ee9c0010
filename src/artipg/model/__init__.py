"""Core model: parts, links, joints and the articulated object."""

from artipg.model.articulation import ArticulatedObject, Joint, Link
from artipg.model.builder import LinkBuilder, ObjectBuilder
from artipg.model.part import Grasp, Part, Region

__all__ = ["ArticulatedObject", "Joint", "Link", "LinkBuilder", "ObjectBuilder", "Grasp", "Part", "Region"]
