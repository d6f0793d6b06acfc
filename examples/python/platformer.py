#!/usr/bin/env python3
"""A small platformer driven over the protocol: how a game uses Impulse.

    python3 examples/python/platformer.py --connect 127.0.0.1:7777

A capsule character walks right along chain terrain. Every tick it asks
the server what lies under its feet (a ray cast that sees only terrain),
walks when it stands on something and jumps at the gap's edge. The coins
are sensors: the server tells the game when the character passes through
one (a sensor event), and the game removes it. The character's shape asks
for hit events, so its hard landings are reported with their speed.

The game runs the world one tick at a time (the world is paused and
stepped), so every run prints the same. The protocol: docs/protocol.md.
"""
import argparse
import sys

from impulse_client import Connection, pb

TERRAIN = 1 << 1
COINS = 1 << 2
CHARACTER = 1 << 3
HALF_HEIGHT = 0.7  # capsule: centres 0.4 above and below its middle, radius 0.3


class Game(Connection):
    """A connection that keeps the Events messages arriving between replies."""

    def __init__(self, host, port):
        super().__init__(host, port)
        self.events = []

    def request(self, **command):
        request_id = self.next_request
        self.next_request += 1
        self.send(pb.ClientMessage(request_id=request_id, **command))
        while True:
            reply = self.receive()
            kind = reply.WhichOneof("message")
            if kind == "events":
                self.events.append(reply.events)
                continue
            if kind == "error":
                raise ConnectionError(reply.error.message)
            return getattr(reply, kind)

    def ok(self, **command):
        result = self.request(**command)
        if not result.ok:
            raise RuntimeError(result.error)
        return result


def flags(category, mask=None, sensor=False, events=False):
    shape_filter = pb.ShapeFilter(category_bits=category)
    if mask is not None:
        shape_filter.mask_bits = mask
    return pb.ShapeFlags(filter=shape_filter, is_sensor=sensor, contact_events=events, hit_events=events)


def build_level(game):
    """Terrain with a gap, three coins, and the character at the left."""
    game.ok(set_paused=pb.SetPaused(paused=True))
    game.ok(clear=pb.ClearWorld())
    # Chains collide on the right of the way their points run: terrain runs
    # right to left, so bodies stand on top of it.
    hills = [(44, 1), (36, 2), (30, 1.5), (26, 1.5), (26, -5)]
    plain = [(22, -5), (22, 1.5), (14, 2.5), (6, 1), (0, 1.5), (-4, 4)]
    for points in (hills, plain):
        game.ok(spawn_chain=pb.SpawnChain(points=[pb.Vec2(x=x, y=y) for x, y in points],
                                          options=pb.BodyOptions(is_static=True,
                                                                 shape_flags=flags(TERRAIN))))
    coins = {}
    for x, y in ((10, 3.0), (24.5, 6.0), (33, 3.0)):
        coin = game.ok(spawn_circle=pb.SpawnCircle(
            center=pb.Vec2(x=x, y=y), radius=0.4,
            options=pb.BodyOptions(is_static=True, shape_flags=flags(COINS, mask=CHARACTER, sensor=True))))
        coins[coin.body_id] = (x, y)
    player = game.ok(spawn_capsule=pb.SpawnCapsule(
        center1=pb.Vec2(x=1, y=2.9), center2=pb.Vec2(x=1, y=3.7), radius=0.3,
        options=pb.BodyOptions(material=pb.RUBBER, restitution=0, friction=0.8,
                               shape_flags=flags(CHARACTER, events=True))))
    return player.body_id, coins


def ground_under(game, position):
    """The terrain point under the character's feet, or None in the air."""
    cast = game.request(ray_cast=pb.RayCast(
        origin=position, translation=pb.Vec2(x=0, y=-(HALF_HEIGHT + 0.25)),
        filter=pb.QueryFilter(category_bits=CHARACTER, mask_bits=TERRAIN)))
    return cast.hits[0] if cast.hits else None


def play(game, player, coins, ticks):
    game.ok(subscribe_events=pb.SubscribeEvents(enabled=True))
    grounded_ticks = 0
    collected = []
    for tick in range(1, ticks + 1):
        state = game.request(query_body=pb.QueryBody(body_id=player)).state
        # Impulse has no fixed-rotation flag yet: the game stands its
        # character up each tick, where it is.
        game.ok(set_transform=pb.SetTransform(body_id=player, position=state.position, angle=0))
        ground = ground_under(game, state.position)
        if ground is not None:
            grounded_ticks += 1
            # Walk right, upright; jump where the plain ends before the gap.
            jump = 20.0 < state.position.x < 21.0
            game.ok(set_velocity=pb.SetVelocity(body_id=player, velocity=pb.Vec2(
                x=5.0, y=8.5 if jump else state.velocity.y), angular_velocity=0))
        else:
            game.ok(set_velocity=pb.SetVelocity(body_id=player, velocity=state.velocity, angular_velocity=0))
        game.ok(step=pb.Step(ticks=1))
        for events in game.events:
            for visit in events.sensor_begins:
                if visit.visitor_body == player and visit.sensor_body in coins:
                    collected.append(visit.sensor_body)
                    print(f"tick {events.tick}: coin {visit.sensor_body} at {coins[visit.sensor_body]} collected")
                    game.ok(remove_body=pb.RemoveBody(body_id=visit.sensor_body))
            for hit in events.hits:
                print(f"tick {events.tick}: landed at {hit.approach_speed:.1f} m/s "
                      f"at ({hit.point.x:.1f}, {hit.point.y:.1f})")
        game.events.clear()
    final = game.request(query_body=pb.QueryBody(body_id=player)).state
    print(f"after {ticks} ticks: character at ({final.position.x:.1f}, {final.position.y:.1f}), "
          f"on the ground {grounded_ticks} ticks, coins {len(collected)} of {len(coins)}")
    return len(collected)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--connect", default="127.0.0.1:7777", help="HOST:PORT of impulse-server")
    parser.add_argument("--ticks", type=int, default=480, help="ticks to play (60 per second)")
    args = parser.parse_args()
    host, port = args.connect.rsplit(":", 1)
    game = Game(host, int(port))
    game.send(pb.ClientMessage(hello=pb.Hello(protocol_version=1, client_name="platformer")))
    if game.receive().WhichOneof("message") != "welcome":
        sys.exit("the server refused the connection")
    player, coins = build_level(game)
    play(game, player, coins, args.ticks)
    return 0


if __name__ == "__main__":
    sys.exit(main())
